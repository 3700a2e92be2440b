// The main of the distributed lane's test programs: starts the processes (MPI with
// -DREVSPH_MPI=ON) around GoogleTest. Only rank 0 prints; the others' results count through their
// exit status, which mpiexec gathers.
#include "core/distributed/processes.hpp"

#include <gtest/gtest.h>

int main(int argc, char** argv) {
  revsph::distributed::ProcessSession session(argc, argv);
  ::testing::InitGoogleTest(&argc, argv);
  if (revsph::distributed::process_rank() != 0) {
    delete ::testing::UnitTest::GetInstance()->listeners().Release(
        ::testing::UnitTest::GetInstance()->listeners().default_result_printer());
  }
  return RUN_ALL_TESTS();
}
