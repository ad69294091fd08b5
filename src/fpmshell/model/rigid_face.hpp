// Where a rigid body's face is, seen from a particle (theory.md §8.3): the outward normal and
// the point of the face below the particle, for the plane (infinite or a rectangle), the sphere
// and the cylinder (infinite or finite) of model-format.md `rigid_bodies`. The contact solver
// linearises the face there for the step; the model reader checks that no particle starts
// inside.
#pragma once

#include "fpmshell/model/model.hpp"

namespace fpmshell {

struct RigidFacePoint {
    bool faces = false;  ///< false: the particle is beyond a finite face's edges (or on an axis)
    Vec3 normal = Vec3::Zero();  ///< unit, outward (towards the particle's side)
    /// the point of the face below the particle, with the body at its initial position (the
    /// face is there plus the body's displacement)
    Vec3 anchor = Vec3::Zero();
};

/// The face of body b, displaced by u, under the particle at y: the particle's distance from
/// the face is normal . (y - anchor - u).
[[nodiscard]] inline RigidFacePoint rigid_face_point(const RigidBody& b, const Vec3& y,
                                                     const Vec3& u) {
    RigidFacePoint f;
    const Vec3 rel = y - (b.point + u);
    switch (b.shape) {
        case RigidShape::Plane: {
            if (b.size_l > 0 || b.size_m > 0) {
                const Real l = b.edge.dot(rel), m = b.normal.cross(b.edge).dot(rel);
                if ((b.size_l > 0 && (l < 0 || l > b.size_l)) ||
                    (b.size_m > 0 && (m < 0 || m > b.size_m)))
                    return f;
            }
            f.faces = true;
            f.normal = b.normal;
            f.anchor = b.point;
            return f;
        }
        case RigidShape::Sphere: {
            const Real r = rel.norm();
            if (!(r > 0)) return f;
            f.faces = true;
            f.normal = rel / r;
            f.anchor = b.point + b.radius * f.normal;
            return f;
        }
        case RigidShape::Cylinder: {
            const Real along = b.axis.dot(rel);
            if (b.length > 0 && (along < 0 || along > b.length)) return f;
            const Vec3 radial = rel - along * b.axis;
            const Real r = radial.norm();
            if (!(r > 0)) return f;
            f.faces = true;
            f.normal = radial / r;
            f.anchor = b.point + along * b.axis + b.radius * f.normal;
            return f;
        }
    }
    return f;
}

}  // namespace fpmshell
