// Homogeneous paths to failure for the failure criteria's tests: a 1 m square of 4 x 4 squares
// of steel (J2, linear hardening) whose particles move by a velocity field, so that every point
// follows one stress state: uniaxial, plane strain, equibiaxial, shear.
#pragma once

#include <cmath>
#include <functional>
#include <vector>

#include "../one_section_model.hpp"
#include "fpmshell/materials/bilinear/bilinear_law.hpp"
#include "fpmshell/mesh/generators.hpp"

namespace fpmshell::test {

/// The plate failing by `criterion`, every particle moved by the velocity field v(x0), or with
/// `lateral_free` by its x velocity only (uniaxial stress; y = 0 on rollers). Its elements'
/// size sqrt(2 A_0) is 0.25 m.
inline Model damaging_path(const std::function<Vec3(const Vec3&)>& velocity, bool lateral_free,
                           const FailureCriterionSpec& criterion) {
    PlateParams pp;
    pp.nx = pp.ny = 4;
    Model m = one_section_model(generate_plate(pp), 0.01, 0.3, 2.0e11, 5);
    make_bilinear(m.materials[0], 2.5e8, 1.0e9);
    m.materials[0].failure.criteria.push_back(criterion);
    m.control.end_time = 1;
    prescribe_velocity_field(m, velocity, {false, false, true, true, true, false},
                             {true, !lateral_free, !lateral_free});
    if (lateral_free) {
        BoundaryCondition roller;
        roller.nodes = m.node_sets.at("ymin");
        roller.fixed[1] = true;
        m.boundary.push_back(roller);
    }
    return m;
}

struct HomogeneousPath {
    const char* name;
    std::function<Vec3(const Vec3&)> velocity;
    bool lateral_free;
    Real eta;  ///< its triaxiality once plastic
};

inline std::vector<HomogeneousPath> homogeneous_paths() {
    return {{"equibiaxial", [](const Vec3& x) { return Vec3(x.x(), x.y(), 0); }, false, 2.0 / 3.0},
            {"plane strain", [](const Vec3& x) { return Vec3(x.x(), 0, 0); }, false,
             1.0 / std::sqrt(3.0)},
            {"uniaxial", [](const Vec3& x) { return Vec3(x.x(), 0, 0); }, true, 1.0 / 3.0},
            {"shear", [](const Vec3& x) { return Vec3(x.y(), 0, 0); }, false, 0.0}};
}

}  // namespace fpmshell::test
