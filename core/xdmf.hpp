#pragma once
// The XDMF (version 2) description of a series of snapshot files, so that ParaView opens a run
// directly: a temporal collection of snapshots, each a spatial collection with one point cloud
// (Polyvertex) per particle set and its per-particle fields as node attributes.

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace revsph {

struct XdmfField {
  std::string name; // dataset /particles/SET/NAME
  int components = 1;
};

struct XdmfParticleSet {
  std::string name;
  std::size_t count = 0;
  std::vector<XdmfField> fields; // must include "position"
};

struct XdmfSnapshot {
  std::int64_t step = 0;
  double time = 0.0;
  std::string file; // relative to the XDMF file
  std::vector<XdmfParticleSet> sets;
};

std::string xdmf_document(int dimension, const std::vector<XdmfSnapshot>& snapshots);

// Writes the document atomically (temporary file, then rename).
void write_xdmf(const std::filesystem::path& path, int dimension,
                const std::vector<XdmfSnapshot>& snapshots);

// The snapshot files an XDMF document of xdmf_document lists, each once, in the order of its
// series, as written there (relative to the XDMF file): the series every reader of a run uses.
std::vector<std::string> xdmf_snapshot_files(const std::string& document);

} // namespace revsph
