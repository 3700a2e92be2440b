// revsph_entropic_discontinuity [OUT.csv]: the discontinuity test of paper 4 (§3.5, Figs. 3-7),
// the particles within 5 h of the jump, as CSV (stdout without an argument), for each reading of
// the right part's entropies (entropic_discontinuity.hpp):
//   right_entropy (spacing | left_value | zero | mass_volume), x, volume (mass | entropic | direct | implicit |
//   mixed), density, entropy_density (inf or nan where a volume divides by S = 0)
// Plot: /usr/bin/python3 tools/plots/entropic_discontinuity.py OUT.csv OUT.png

#include "csv_program.hpp"
#include "entropic_discontinuity.hpp"

#include <cmath>
#include <iomanip>
#include <iostream>

int main(int argc, char** argv) {
  using namespace revsph::analysis;
  return run_csv_program(argc, argv, "revsph_entropic_discontinuity", [](std::ostream& out) {
    out << "right_entropy,x,volume,density,entropy_density\n" << std::setprecision(17);
    for (const RightEntropy right : right_entropies) {
      const DiscontinuityProfiles profiles = entropic_discontinuity(right);
      for (std::size_t v = 0; v < discontinuity_volumes.size(); ++v) {
        for (std::size_t i = 0; i < profiles.x.size(); ++i) {
          if (std::fabs(profiles.x[i] - 0.5) <= 5e-3) {
            out << name_of(right) << ',' << profiles.x[i] << ','
                << name_of(discontinuity_volumes[v]) << ',' << profiles.density[v][i] << ','
                << profiles.entropy_density[v][i] << '\n';
          }
        }
      }
    }
  });
}
