// revsph_entropic_quadrature [OUT.csv]: the quadrature test of paper 4 (§3.4, Fig. 2) for ten
// particle counts N from about 100 to 40 000, log-spaced, as CSV (stdout without an argument):
//   N, dr, volume (mass | implicit), function (f1 | f2 | f3), quadrature, exact, relative_error,
//   volume_sum (sum_a V_a over [0,1]^2: the quadrature of 1, whose error is the lattice's bias)
// Plot: /usr/bin/python3 tools/plots/entropic_quadrature.py OUT.csv OUT.png

#include "csv_program.hpp"
#include "entropic_quadrature.hpp"

#include <cmath>
#include <cstdio>
#include <iostream>

int main(int argc, char** argv) {
  using namespace revsph::analysis;
  return run_csv_program(argc, argv, "revsph_entropic_quadrature", [](std::ostream& out) {
    out << "N,dr,volume,function,quadrature,exact,relative_error,volume_sum\n";
    constexpr int counts = 10;
    for (int i = 0; i < counts; ++i) {
      const double target = 100.0 * std::pow(400.0, static_cast<double>(i) / (counts - 1));
      const QuadratureResult r = entropic_quadrature(columns_for(target));
      for (const QuadratureVolume volume : {QuadratureVolume::mass, QuadratureVolume::implicit}) {
        for (int f = 0; f < 3; ++f) {
          char line[256];
          std::snprintf(line, sizeof line, "%zu,%.10g,%s,%s,%.16g,%.16g,%.6e,%.16g\n", r.particles,
                        r.dr, name_of(volume).data(), quadrature_functions()[f].name.data(),
                        r.quadrature[static_cast<int>(volume)][f], quadrature_functions()[f].exact,
                        r.relative_error(volume, f), r.volume_sum[static_cast<int>(volume)]);
          out << line;
        }
      }
      std::cerr << "N = " << r.particles << " (+" << r.dummies << " dummies): W V = 1 in "
                << r.solver_iterations << " CG iterations\n";
    }
  });
}
