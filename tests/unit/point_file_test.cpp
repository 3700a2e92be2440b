// Point files (core/point_file.hpp) and what fill_set gives a set from them
// (core/state_fill.hpp): CSV and HDF5 read to the same columns; a header without units, a row of
// the wrong length, a value that is no number, a position not in metres are one-line errors
// naming the file and line; a file's values reach the particles it places, in their field's
// unit, and a copy filled from the same values gets them too; a case given a block's file (by a
// snapshot) reads that, not the disk.

#include "core/arithmetic.hpp"
#include "core/case_file.hpp"
#include "core/common_fields.hpp"
#include "core/hdf5_handle.hpp"
#include "core/particle_blocks.hpp"
#include "core/point_file.hpp"
#include "core/sha256.hpp"
#include "core/state_fill.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <tuple>
#include <vector>

namespace revsph {
namespace {

namespace fs = std::filesystem;

class PointFileTest : public testing::Test {
protected:
  void SetUp() override {
    folder_ =
        fs::temp_directory_path() / ("revsph-point-file-" + std::to_string(::getpid()) + "-" +
                                     testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }
  fs::path write(const std::string& name, const std::string& text) {
    std::ofstream(folder_ / name) << text;
    return folder_ / name;
  }
  // The error read_point_file<2> throws for `text`, or "" if it reads.
  std::string refusal(const std::string& text) {
    try {
      read_point_file<2>(write("bad.csv", text));
    } catch (const PointFileError& error) {
      return error.what();
    }
    return "";
  }
  fs::path folder_;
};

TEST_F(PointFileTest, ReadsPositionsAndNamedColumnsWithUnitsFromCsv) {
  const PointFile<2> file = read_point_file<2>(write("ok.csv", "# a comment\n"
                                                               "velocity_x [m/s], x [m], y [m]\n"
                                                               "1.5, 0.25, -1e-3\n"
                                                               "\n"
                                                               " -2 , 0.75 , 2.0\n"));
  ASSERT_EQ(file.positions.size(), 2u);
  EXPECT_EQ(file.positions[0][0], 0.25);
  EXPECT_EQ(file.positions[0][1], -1e-3);
  EXPECT_EQ(file.positions[1][1], 2.0);
  ASSERT_EQ(file.columns.size(), 1u);
  EXPECT_EQ(file.columns[0].name, "velocity_x");
  EXPECT_EQ(file.columns[0].unit, "m/s");
  EXPECT_EQ(file.columns[0].values, (std::vector<double>{1.5, -2.0}));
}

TEST_F(PointFileTest, BadCsvIsOneLineNamingFileAndLine) {
  EXPECT_NE(refusal("x, y [m]\n0, 0\n").find("has no unit"), std::string::npos);
  EXPECT_NE(refusal("x [m], y [m]\n0, 0\n1, 2, 3\n").find("line 3: 3 values for 2 columns"),
            std::string::npos);
  EXPECT_NE(refusal("x [m], y [m]\n0, nan\n").find("not a finite number"), std::string::npos);
  EXPECT_NE(refusal("x [m], y [m]\n0, 1.5.2\n").find("line 2"), std::string::npos);
  EXPECT_NE(refusal("x [mm], y [m]\n0, 0\n").find("positions are in [m]"), std::string::npos);
  EXPECT_NE(refusal("x [m], z [m]\n0, 0\n").find("a column z in a 2D case"), std::string::npos);
  EXPECT_NE(refusal("x [m]\n0\n").find("no position column y"), std::string::npos);
  EXPECT_NE(refusal("x [m], y [m], x [m]\n0, 0, 0\n").find("appears twice"), std::string::npos);
  EXPECT_NE(refusal("x [m], y [m]\n").find("no particles"), std::string::npos);
  EXPECT_NE(refusal("").find("empty"), std::string::npos);
  EXPECT_EQ(refusal("x [m], y [m]\n0, 0\n"), "");
}

// A spreadsheet's UTF-8 export starts with a byte-order mark: the header is read after it.
TEST_F(PointFileTest, ByteOrderMarkBeforeTheHeaderIsSkipped) {
  EXPECT_EQ(refusal("\xEF\xBB\xBFx [m], y [m]\n0, 0\n"), "");
  const PointFile<2> file =
      read_point_file<2>(write("bom.csv", "\xEF\xBB\xBFx [m], y [m], mass [kg/m]\n0, 0, 2\n"));
  ASSERT_EQ(file.columns.size(), 1u);
  EXPECT_EQ(file.columns[0].name, "mass");
}

// Two rows at one position: the second would be a particle the file's values never reach.
TEST_F(PointFileTest, RepeatedPositionIsRefusedNamingBothLines) {
  const std::string csv = "# points\nx [m], y [m]\n0, 0\n1, 0.5\n0, 1\n1, 0.5\n";
  const std::string error = refusal(csv);
  EXPECT_NE(error.find("bad.csv line 6: the same position as line 4"), std::string::npos) << error;
  EXPECT_EQ(refusal("x [m], y [m]\n0, 0\n0, 1e-300\n"), ""); // near is not the same
}

// Rows closer than the set-up's tolerance (1e-6 of the spacing) but not equal: one point block's
// own particles on each other, refused as two blocks' are (core/coincident_particles.hpp).
TEST_F(PointFileTest, ParticlesOfOneBlockOnEachOtherAreRefused) {
  write("near.csv", "x [m], y [m]\n0.5, 0.5\n0.2, 0.2\n0.5, 0.5000000001\n");
  const CaseFile case_file =
      CaseFile::parse("[domain]\nmin = [0, 0]\nmax = [1, 1]\n[[particles]]\nkind = \"fluid\"\n"
                      "shape = \"points\"\nfile = \"near.csv\"\n",
                      (folder_ / "case.toml").string());
  constexpr std::string_view kinds[] = {"fluid"};
  std::string error;
  try {
    read_particle_blocks<2>(case_file, 0.1, read_domain<2>(case_file), kinds,
                            ParticleBudget{400.0, std::size_t{1} << 30});
  } catch (const CaseError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("particles[0]: particle 2 at (0.5, 0.5) lies on its particle 0"),
            std::string::npos)
      << error;
}

// A file named as HDF5 that is not (a CSV renamed, a truncated download) is not read as CSV.
TEST_F(PointFileTest, FileNamedH5WithoutTheHdf5SignatureIsRefused) {
  std::string error;
  try {
    read_point_file<2>(write("points.h5", "x [m], y [m]\n0, 0\n"));
  } catch (const PointFileError& e) {
    error = e.what();
  }
  EXPECT_NE(error.find("points.h5: named .h5 but not an HDF5 file"), std::string::npos) << error;
  EXPECT_NO_THROW(read_point_file<2>(write("points.txt", "x [m], y [m]\n0, 0\n")));
}

// h5py's way: one dataset per field, (N) or (N, C), with a unit attribute.
void write_dataset(hid_t file, const char* name, const std::vector<double>& rows, hsize_t count,
                   hsize_t components, const char* unit) {
  const hsize_t dims[2] = {count, components};
  const hdf5::Handle space(H5Screate_simple(components == 1 ? 1 : 2, dims, nullptr), H5Sclose,
                           "space");
  const hdf5::Handle dataset(
      H5Dcreate2(file, name, H5T_NATIVE_DOUBLE, space.id(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose, "dataset");
  H5Dwrite(dataset.id(), H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, rows.data());
  hdf5::write_string_attribute(dataset.id(), "unit", unit);
}

TEST_F(PointFileTest, Hdf5DatasetsReadAsTheSameColumnsAsCsv) {
  const fs::path path = folder_ / "points.h5";
  {
    const hdf5::Handle file(H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT),
                            H5Fclose, "file");
    write_dataset(file.id(), "position", {0.25, -1e-3, 0.75, 2.0}, 2, 2, "m");
    write_dataset(file.id(), "velocity", {1.5, 3.0, -2.0, 4.0}, 2, 2, "m/s");
    write_dataset(file.id(), "entropy", {7.0, 8.0}, 2, 1, "J/(kg K)");
  }
  const PointFile<2> file = read_point_file<2>(path);
  ASSERT_EQ(file.positions.size(), 2u);
  EXPECT_EQ(file.positions[1][0], 0.75);
  ASSERT_EQ(file.columns.size(), 3u); // in name order: entropy, velocity
  EXPECT_EQ(file.columns[0].name, "entropy");
  EXPECT_EQ(file.columns[0].unit, "J/(kg K)");
  EXPECT_EQ(file.columns[1].name, "velocity_x");
  EXPECT_EQ(file.columns[2].name, "velocity_y");
  EXPECT_EQ(file.columns[2].values, (std::vector<double>{3.0, 4.0}));

  // What the CSV writer writes reads back the same.
  write_point_csv<2>(folder_ / "again.csv", file);
  const PointFile<2> again = read_point_file<2>(folder_ / "again.csv");
  EXPECT_EQ(again.positions, file.positions);
  EXPECT_EQ(again.columns[1].values, file.columns[1].values);
}

// A block reads its file once from disk, relative to the case, and keeps its bytes; a case given
// the file (by a snapshot) reads that, with the disk's copy gone.
TEST_F(PointFileTest, ABlockReadsTheFileItsCaseWasGivenNotTheDisk) {
  const std::string on_disk = "x [m], y [m]\n0.5, 0.5\n";
  write("fluid.csv", on_disk);
  const std::string text = "[[particles]]\nshape = \"points\"\nfile = \"fluid.csv\"\n";
  const std::string source = (folder_ / "case.toml").string();
  const CaseFile from_disk = CaseFile::parse(text, source);
  EXPECT_EQ(read_point_file<2>(block_input_file(from_disk, "particles[0]")).positions.size(), 1u);
  ASSERT_EQ(from_disk.inputs().used().size(), 1u);
  EXPECT_EQ(from_disk.inputs().used()[0].sha256, sha256_hex(on_disk));
  EXPECT_EQ(from_disk.inputs().used()[0].path, (folder_ / "fluid.csv").string());

  fs::remove(folder_ / "fluid.csv");
  const std::string kept = "x [m], y [m]\n0.25, 0.75\n1, 1\n";
  const CaseFile from_snapshot = CaseFile::parse(text, source);
  from_snapshot.inputs().give({"fluid.csv", "/elsewhere/fluid.csv", sha256_hex(kept), kept});
  EXPECT_EQ(read_point_file<2>(block_input_file(from_snapshot, "particles[0]")).positions.size(),
            2u);
  ASSERT_EQ(from_snapshot.inputs().used().size(), 1u);
  EXPECT_EQ(from_snapshot.inputs().used()[0].bytes, kept);
}

// A set like a model's fluid: velocity and a copy of it filled from the same values.
struct Fluid {
  static constexpr SetInfo set{.name = "fluid", .motion = Motion::moving};
  StateField<std::int64_t> position{position_field<2>()};
  StateField<std::int64_t> velocity{
      {.name = "velocity", .unit = "m/s", .parity = Parity::odd, .components = 2}};
  StateField<std::int64_t> velocity_copy{{.name = "velocity_copy",
                                          .unit = "m/s",
                                          .parity = Parity::odd,
                                          .components = 2,
                                          .scaled_as = "velocity"}};
  // Starting equal to the velocity but not its copy (superfluid's wall).
  StateField<std::int64_t> superflow_velocity{{.name = "superflow_velocity",
                                               .unit = "m/s",
                                               .parity = Parity::odd,
                                               .components = 2,
                                               .scaled_as = "velocity"}};
  StateField<std::int64_t> mass{mass_field<2>()};
  StateField<std::int64_t> density_constant{density_constant_field()};
  auto fields() {
    return std::tie(position, velocity, velocity_copy, superflow_velocity, mass, density_constant);
  }
};

class FillFromPointFile : public PointFileTest {
protected:
  // fill_set's error for a fluid whose particles are a box block's two and the file's two; the
  // set-up's density (as wcsph's) may be given as `density` or as a pressure twice the density.
  std::string fill(const std::string& csv, Fluid& fluid) {
    std::vector<double> density(4, 1.0);
    return fill(csv, fluid, density);
  }
  std::string fill(const std::string& csv, Fluid& fluid, std::vector<double>& density) {
    write("fluid.csv", csv);
    const CaseFile case_file =
        CaseFile::parse("[[particles]]\nkind = \"fluid\"\nmin = [0, 0]\nmax = [1, 1]\n"
                        "[[particles]]\nkind = \"fluid\"\nshape = \"points\"\n"
                        "file = \"fluid.csv\"\n",
                        (folder_ / "case.toml").string());
    for (auto* field : {&fluid.position, &fluid.velocity, &fluid.velocity_copy,
                        &fluid.superflow_velocity, &fluid.mass, &fluid.density_constant}) {
      field->set_scale(fixedpoint::Scale(-40));
    }
    const std::vector<Vec<2>> positions = {{0.5, 0.5}, {0.1, 0.2}, {3.0, 4.0}, {2.0, 0.25}};
    const std::vector<Vec<2>> velocities(4, Vec<2>{9.0, 9.0});
    const std::vector<double> masses(4, 0.5);
    const SetUpValue as_density{.name = "density",
                                .unit = "kg/m^3",
                                .values = density,
                                .from_file = [](double d) { return d > 0.0 ? d : std::nan(""); },
                                .admits = "above 0",
                                .what = "the density"};
    const SetUpValue as_pressure{.name = "pressure",
                                 .unit = "Pa",
                                 .values = density,
                                 .from_file = [](double p) { return 0.5 * p; },
                                 .admits = "",
                                 .what = "the density"};
    try {
      fill_set<FixedArithmetic, 2>(case_file, fluid, 4,
                                   {{"position", "particles", positions},
                                    {"velocity", "initial.field", velocities},
                                    {"velocity_copy", "initial.field", velocities},
                                    {"superflow_velocity", "initial.field", velocities},
                                    {"mass", "physics.rest_density", masses},
                                    {"density_constant", "particles", 0.0}},
                                   {as_density, as_pressure});
    } catch (const CaseError& error) {
      return error.what();
    }
    return "";
  }
  static double velocity(const StateField<std::int64_t>& field, int k, std::size_t i) {
    return fixedpoint::to_real(field.at(k, i), field.info().scale);
  }
};

TEST_F(FillFromPointFile, GivesTheFilesValuesToTheParticlesItPlacesAndToCopies) {
  Fluid fluid;
  ASSERT_EQ(fill("x [m], y [m], velocity_y [m/s], velocity_x [m/s]\n2.0, 0.25, -1.5, 2.5\n"
                 "3.0, 4.0, 0.5, 0.5\n",
                 fluid),
            "");
  EXPECT_EQ(velocity(fluid.velocity, 1, 3), -1.5);
  EXPECT_EQ(velocity(fluid.velocity, 1, 2), 0.5);
  EXPECT_EQ(velocity(fluid.velocity_copy, 1, 3), -1.5);
  EXPECT_EQ(velocity(fluid.velocity, 0, 3), 2.5);
  EXPECT_EQ(fixedpoint::to_real(fluid.mass.at(0, 3), fluid.mass.info().scale), 0.5); // the set-up's
  EXPECT_EQ(velocity(fluid.velocity, 1, 0), 9.0);            // the box block's particle
  EXPECT_EQ(velocity(fluid.superflow_velocity, 1, 3), -1.5); // starts equal to the velocity
  ASSERT_EQ(fill("x [m], y [m], superflow_velocity_y [m/s], superflow_velocity_x [m/s], "
                 "velocity_x [m/s], velocity_y [m/s]\n2.0, 0.25, 4, 3, 1, 2\n",
                 fluid),
            "");
  EXPECT_EQ(velocity(fluid.superflow_velocity, 1, 3), 4.0); // each given its own
  EXPECT_EQ(velocity(fluid.velocity, 1, 3), 2.0);
  EXPECT_EQ(velocity(fluid.velocity_copy, 1, 3), 2.0);
  EXPECT_NE(
      fill("x [m], y [m], velocity_copy_x [m/s], velocity_copy_y [m/s]\n2.0, 0.25, 1, 1\n", fluid)
          .find("no such initial value"),
      std::string::npos); // a copy starts as its original
}

TEST_F(FillFromPointFile, RefusesWrongUnitsUnknownFieldsConstantsAndMovedParticles) {
  Fluid fluid;
  EXPECT_NE(fill("x [m], y [m], velocity_y [km/h]\n2.0, 0.25, 1\n", fluid)
                .find("velocity_y is in [km/h]; the field is in [m/s]"),
            std::string::npos);
  const std::string unknown = fill("x [m], y [m], speed [m/s]\n2.0, 0.25, 1\n", fluid);
  EXPECT_NE(unknown.find("column speed: no such initial value of set fluid"), std::string::npos);
  EXPECT_NE(unknown.find("velocity_x [m/s]"), std::string::npos) << unknown;
  EXPECT_NE(fill("x [m], y [m], density_constant [kg/m^3]\n2.0, 0.25, 1\n", fluid)
                .find("no such initial value"),
            std::string::npos);
  EXPECT_NE(fill("x [m], y [m], velocity_y [m/s]\n2.0, 0.26, 1\n", fluid)
                .find("not where the set-up left it"),
            std::string::npos);
  EXPECT_NE(fill("x [m], y [m], velocity_y [m/s], velocity_x [m/s]\n2.0, 0.25, 1e300, 0\n", fluid)
                .find("does not fit its fixed-point scale"),
            std::string::npos);
}

// A mass of zero or less ended as a run fault ("density not positive"): bad input, naming the
// file's line and column.
TEST_F(FillFromPointFile, MassNotPositiveNamesTheLineAndColumn) {
  Fluid fluid;
  const std::string error =
      fill("x [m], y [m], mass [kg/m]\n# second\n2.0, 0.25, 0.5\n3.0, 4.0, -0.25\n", fluid);
  EXPECT_NE(error.find("particles[1].file: "), std::string::npos) << error;
  EXPECT_NE(error.find("fluid.csv line 4, column mass: -0.25 [kg/m], but a mass is positive"),
            std::string::npos)
      << error;
  EXPECT_NE(fill("x [m], y [m], mass [kg/m]\n2.0, 0.25, 0\n", fluid).find("line 2, column mass"),
            std::string::npos);
  EXPECT_EQ(fill("x [m], y [m], mass [kg/m]\n2.0, 0.25, 0.75\n", fluid), "");
  EXPECT_EQ(fixedpoint::to_real(fluid.mass.at(0, 3), fluid.mass.info().scale), 0.75);
}

// velocity_x alone would leave velocity_y at the set-up's value: the missing column is named.
TEST_F(FillFromPointFile, PartOfAVectorIsRefusedNamingTheMissingColumn) {
  Fluid fluid;
  EXPECT_NE(fill("x [m], y [m], velocity_x [m/s]\n2.0, 0.25, 1\n", fluid)
                .find("no column velocity_y [m/s]: a file gives every component of velocity or "
                      "none"),
            std::string::npos);
  EXPECT_EQ(fill("x [m], y [m], velocity_y [m/s], velocity_x [m/s]\n2.0, 0.25, 1, 2\n", fluid), "");
}

// A set-up value (wcsph's initial density): given directly or converted from another quantity,
// one of them per file; a value the model does not admit names its line and column.
TEST_F(FillFromPointFile, SetUpValuesReachTheParticlesTheFilePlaces) {
  Fluid fluid;
  std::vector<double> density(4, 1.0);
  ASSERT_EQ(fill("x [m], y [m], pressure [Pa]\n2.0, 0.25, 3\n3.0, 4.0, 5\n", fluid, density), "");
  EXPECT_EQ(density, (std::vector<double>{1.0, 1.0, 2.5, 1.5}));
  ASSERT_EQ(fill("x [m], y [m], density [kg/m^3]\n3.0, 4.0, 7\n", fluid, density), "");
  EXPECT_EQ(density[2], 7.0);
  EXPECT_NE(fill("x [m], y [m], density [kg/m^3]\n2.0, 0.25, 0\n", fluid)
                .find("fluid.csv line 2, column density: 0 [kg/m^3], but it must be above 0"),
            std::string::npos);
  EXPECT_NE(fill("x [m], y [m], density [kg/m^3], pressure [Pa]\n2.0, 0.25, 1, 2\n", fluid)
                .find("columns density and pressure give one thing (the density): give one of "
                      "them"),
            std::string::npos);
}

} // namespace
} // namespace revsph
