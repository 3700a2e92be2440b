// The declarations of the keys that core reads for every model: model (core/model_registry.cpp),
// name, [run] and [output] (core/run_settings.cpp), [domain] and [[particles]]
// (core/particle_blocks.cpp). Keep them next to those readers' checks when either changes.

#include "core/case_keys.hpp"

namespace revsph {

const KeyTable& common_case_keys() {
  static const KeyTable table = [] {
    KeyTable t("common");
    t.add({"model", KeyType::string, "-", "required",
           "the model that reads the rest of the file (revsph cases lists them)"});
    t.add({"name", KeyType::string, "-", "the file name without .toml",
           "the case's name, written into snapshots and the run summary"});
    t.add({"run.steps", KeyType::integer, "-", "none (or run.t_end)",
           "steps `revsph run` takes without --steps or --t-end; >= 0; not with t_end"});
    t.add({"run.t_end", KeyType::number, "s", "none (or run.steps)",
           "time `revsph run` reaches without --steps or --t-end (t_end / dt steps, rounded); "
           "> 0; not with steps"});
    t.add(
        {"output.energy_every", KeyType::integer, "-", "100", "steps between rows of energy.csv"});
    t.add({"output.snapshot_every", KeyType::integer, "-", "0",
           "steps between snapshots (0: only at the start and the end)"});
    t.add({"output.progress_interval", KeyType::number, "s", "10",
           "seconds between progress lines when the output is not a terminal"});
    return t;
  }();
  return table;
}

std::vector<KeyDecl> domain_case_keys() {
  return {
      {"domain.min", KeyType::numbers, "m", "required",
       "lower corner of the domain, one number per axis; every particle must lie inside"},
      {"domain.max", KeyType::numbers, "m", "required",
       "upper corner of the domain; greater than domain.min on every axis"},
  };
}

std::vector<KeyDecl> particle_block_case_keys(const std::vector<std::string>& kinds) {
  return {
      {"particles", KeyType::tables, "-", "required",
       "[[particles]] blocks: regions filled with particles, each one table"},
      {"particles[].kind", KeyType::string, "-", "required", "which particle set the block fills",
       kinds},
      {"particles[].shape",
       KeyType::string,
       "-",
       "\"box\"",
       "\"box\": the region [min, max] filled; \"container\": `layers` lattice layers around the "
       "box [min, max]; \"annulus\" (2D): concentric rings between inner_radius and "
       "outer_radius about centre; \"outline\" (2D): a polygon with rounded corners (vertices, "
       "corner_radii), filled on a square lattice",
       {"box", "container", "annulus", "outline"}},
      {"particles[].lattice",
       KeyType::string,
       "-",
       "\"square\"",
       "\"hexagonal\": triangular (2D) or hexagonal close packed (3D); \"bcc\" (3D): "
       "body-centred cubic, two particles per cube of side spacing; \"vogel\" (2D): a Vogel "
       "spiral about the region's centre, one particle per spacing^2; not for an annulus",
       {"square", "hexagonal", "bcc", "vogel"}},
      {"particles[].spacing", KeyType::number, "m", "discretisation.dr", "lattice spacing; > 0"},
      {"particles[].min", KeyType::numbers, "m", "required (not for an annulus)",
       "lower corner of the region (of the hollow for a container)"},
      {"particles[].max", KeyType::numbers, "m", "required (not for an annulus)",
       "upper corner of the region; greater than min on every axis"},
      {"particles[].layers", KeyType::integer, "-", "1",
       "a container's wall thickness in lattice layers, 1 to 1000; an outline's: only the "
       "particles within layers * spacing of its boundary (default: filled)"},
      {"particles[].open_top", KeyType::boolean, "-", "false",
       "a container without its top wall (containers only)"},
      {"particles[].vertices", KeyType::numbers, "m", "required for an outline",
       "an outline's vertices in order, x0, y0, x1, y1, ... (three or more)"},
      {"particles[].corner_radii", KeyType::numbers, "m", "all 0",
       "one radius per vertex: the corner becomes the arc of that radius tangent to both edges "
       "(a convex corner rounded, a concave one filled); 0: sharp"},
      {"particles[].mirror_x", KeyType::boolean, "-", "false",
       "an outline reflected x -> -x (before its offset)"},
      {"particles[].offset", KeyType::numbers, "m", "[0, 0]", "an outline moved by this vector"},
      {"particles[].lattice_origin", KeyType::numbers, "m", "[0, 0]",
       "an outline's lattice points are origin + (i + 1/2, j + 1/2) spacing: give a box "
       "block's min to continue its lattice"},
      {"particles[].exclude_blocks", KeyType::numbers, "-", "none",
       "indices of box or outline blocks (0-based) whose regions this block leaves out (a fluid "
       "around solid bodies)"},
      {"particles[].centre", KeyType::numbers, "m", "required for an annulus",
       "an annulus's centre (2 numbers)"},
      {"particles[].inner_radius", KeyType::number, "m", "required for an annulus",
       "an annulus's inner radius, >= 0"},
      {"particles[].outer_radius", KeyType::number, "m", "required for an annulus",
       "an annulus's outer radius, at least one spacing beyond inner_radius"},
  };
}

} // namespace revsph
