// common/io/volume_nrrd.h — scalar volumes (field::Grid3) as NRRD files,
// read and written with Teem's nrrd library (https://teem.sourceforge.net/nrrd/).
//
// Reading takes any 3-D NRRD that Teem reads: any scalar type (converted to
// float, values unchanged: a uint8 volume reads as 0..255), raw, ASCII, hex,
// gzip or bzip2 data, attached or detached (.nhdr) headers. Axis 0 is x
// (fastest), as in Grid3. The spacing comes from "space directions" (they
// must be axis-aligned and positive) or else from "spacings" (1 if neither);
// the origin from "space origin" (0 if absent).
//
// Writing makes a raw-encoded NRRD with "space dimension: 3", diagonal
// "space directions" (the spacing) and "space origin", written atomically
// (temporary file + rename) like the JSON files; a path that is no regular
// file (/dev/stdout) is written in place.
//
// A bad file throws FileError (spline_json.h) with one line naming the file:
//   "volume.nrrd: 2 dimensions, need 3"
#pragma once

#include <string>

#include "field/grid.h"

namespace gllab::io {

/// Throws FileError: cannot open, not a NRRD Teem reads, not 3-D, an axis
/// with fewer than 2 samples, truncated data, a non-finite value, space
/// directions that are not axis-aligned.
field::Grid3 read_nrrd(const std::string& path);

/// Writes grid as "type: float" (native endian), raw. content, when not
/// empty, becomes the NRRD "content:" field. Throws FileError when the file
/// cannot be written, std::invalid_argument when the grid is malformed (sizes
/// below 2, values.size() != nx ny nz, spacing not positive and finite).
void write_nrrd(const field::Grid3& grid, const std::string& path, const std::string& content = "");

/// Writes grid as "type: uchar", raw, quantised: round(255 (v - lo) / (hi - lo))
/// clamped to 0..255, with "old min: lo" and "old max: hi" recording the
/// mapping (reading gives back the 0..255 values). Needs lo < hi, finite.
void write_nrrd_uint8(const field::Grid3& grid, const std::string& path, double lo, double hi,
                      const std::string& content = "");

}  // namespace gllab::io
