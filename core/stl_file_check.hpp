#pragma once
// The check of an STL file before CGAL reads it, naming the place of a fault: CGAL's reader skips
// words it does not know, reports a number it cannot read without saying where, and merges a NaN
// corner with another point, so a garbled line or a NaN would otherwise pass or be reported
// without its place. An ASCII file is checked line by line against
//
//   solid [name]
//     facet normal NX NY NZ        (the normal is not used: three numbers, any value)
//       outer loop
//         vertex X Y Z             (three finite numbers), three times
//       endloop
//     endfacet
//   endsolid [name]                (a file may hold several solids)
//
// and a binary one (80 bytes of header, the triangle count n, then 50 bytes per triangle) for
// its size and the finiteness of its corners.

#include <optional>
#include <string>

namespace revsph {

// Whether the file's bytes are ASCII STL: it starts with the word "solid" and its size is not the one a
// binary file's triangle count gives (84 + 50 n bytes; a binary header may start with "solid").
bool is_ascii_stl(const std::string& bytes);

// The first fault of an STL file's bytes as "line 17: reason" (ASCII) or "triangle 17: reason"
// (binary), or nothing.
std::optional<std::string> stl_file_fault(const std::string& bytes);

} // namespace revsph
