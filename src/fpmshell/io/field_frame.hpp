// One output frame of the field series (fields/frame_NNNNN.vtu): plain data, filled by the
// solver's output observer and read by the VTU writer. Units are those of the model file.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

/// A named array with `components` values per point (or per cell), stored point after point:
/// values[i * components + c]. Invariant: values.size() == n * components, where n is the
/// number of points (point data) or triangles (cell data) of the frame.
struct FieldArray {
    std::string name;    ///< shown in ParaView; keep it free of '"', '<' and '&' (they are escaped)
    int components = 1;  ///< 1 scalar, 3 vector, 6 symmetric tensor, 9 tensor, ...
    std::vector<Real> values;
};

/// Geometry and fields of the shell at one time.
struct FieldFrame {
    Real time = 0;                                ///< simulated time of the frame
    std::vector<Vec3> points;                     ///< current particle positions
    std::vector<std::array<Index, 3>> triangles;  ///< indices into points
    std::vector<FieldArray> point_data;           ///< per particle
    std::vector<FieldArray> cell_data;            ///< per triangle
};

}  // namespace fpmshell
