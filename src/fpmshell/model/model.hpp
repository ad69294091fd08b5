// The Model: everything the solver needs, as plain validated data (model-format.md).
// It is built once by io/model_reader from the YAML file and never changes during a run
// (the "Starter" half of the OpenRadioss split; the solver is the "Engine").
#pragma once

#include <any>
#include <array>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "fpmshell/core/types.hpp"
#include "fpmshell/loads/blast/blast_load.hpp"

namespace fpmshell {

/// Piecewise-linear (time, factor) curve, held flat past its ends (model-format.md `curves`).
struct Curve {
    std::string name;
    std::vector<std::pair<Real, Real>> points;  ///< sorted by time, at least one point

    /// Factor at time t (flat extrapolation before the first and after the last point).
    [[nodiscard]] Real value(Real t) const;
    /// Integral of the factor from 0 to t, exact for the piecewise-linear curve.
    [[nodiscard]] Real integral(Real t) const;
};

/// Factor of curves[curve] at time t; 1 at all times for curve -1 (no curve).
[[nodiscard]] Real curve_factor(const std::vector<Curve>& curves, Index curve, Real t);
/// Integral of that factor from 0 to t (t for curve -1).
[[nodiscard]] Real curve_factor_integral(const std::vector<Curve>& curves, Index curve, Real t);

/// One failure criterion of a material: its name (its key under `failure`, a criterion of
/// failure/failure_criteria.cpp) and its constants, of the type its folder declares.
struct FailureCriterionSpec {
    std::string name;
    std::any parameters{};
};

/// How a plastic material's points fail and its elements erode (theory.md §7.6;
/// failure/element_erosion.hpp): a point fails when one of its criteria says so.
struct MaterialFailure {
    std::vector<FailureCriterionSpec> criteria{};
    /// failed points that erode an element; 0: every point through the thickness at one of
    /// its in-plane points
    int points = 0;
    /// instead of points: the fraction of its layers through the thickness that erodes an
    /// element, a layer failed where one of its points has (LS-DYNA's NUMFIP < 0); 0: not used
    Real layer_fraction = 0;
    /// What a failed element does: erodes (stops acting, §7.6), or, with `fracture:
    /// separate`, keeps acting and opens one of its edges, the particles separating along the
    /// open edges (§7.7)
    bool separates = false;
    /// An element erodes once its step (time_step_scale x its critical step) falls below it
    /// (LS-DYNA's *MAT_024 and *MAT_081 TDEL); 0: never
    Real minimum_time_step = 0;

    [[nodiscard]] bool active() const { return !criteria.empty() || minimum_time_step > 0; }
};

/// A material: the constants every law has, and its law's own (units as in the model file;
/// never converted). The law is a folder under materials/ and a line of
/// materials/material_laws.cpp, which reads its keys into `parameters` and makes the element
/// group of its sections; nothing else looks into `parameters`.
struct Material {
    std::string name;
    std::string law = "elastic";  ///< the model file's `type` (materials/material_laws.cpp)
    Real density = 0;             ///< rho
    Real youngs_modulus = 0;      ///< E
    Real poisson_ratio = 0;       ///< nu
    /// the law's constants, of the type its folder declares (std::any: copied with the model)
    std::any parameters{};
    /// a plastic law: it dissipates plastic work, takes failure criteria, and its sections
    /// default to 5 points through the thickness (set from the law's registry line)
    bool plastic_law = false;
    /// `type: rigid` (an elastic material here): each section of it moves as one rigid body
    /// (solver/nodal_rigid_bodies.hpp) and its elements do not limit the time step
    bool rigid = false;
    /// rigid: the body's velocity components held at zero, translations along x, y, z then
    /// rotations about x, y, z (global axes; LS-DYNA's *MAT_RIGID CMO = 1 with CON1, CON2)
    std::array<bool, 6> rigid_fixed{};

    /// plastic materials: failure and erosion (none by default)
    MaterialFailure failure{};

    [[nodiscard]] bool plastic() const { return plastic_law; }
};

/// The family of a section's points through the thickness (theory.md §4.5). ByCount is the
/// default of model-format.md: Gauss for 1 or 2 points, Lobatto for 3 or more.
enum class ThicknessRule { ByCount, Gauss, Lobatto, User };

/// The mass properties a section of a rigid material gives its rigid body in place of its
/// elements' (LS-DYNA's *PART_INERTIA; a rigid part meshed with solids, theory.md §6.11):
/// its mass, centre of mass and inertia tensor about that centre in global axes, at t = 0.
struct RigidInertia {
    Real mass = 0;
    Vec3 centre = Vec3::Zero();
    Mat3 tensor = Mat3::Zero();  ///< symmetric positive definite
};

/// Shell section of a group of elements.
struct Section {
    Index material = -1;       ///< index into Model::materials
    Real thickness = 0;        ///< h
    int thickness_points = 2;  ///< Gauss 1-10 or Lobatto 3-10; a user rule's count
    int inplane_points = 3;    ///< 3 or 7 (theory.md §4.5, §7.5)
    ThicknessRule thickness_rule = ThicknessRule::ByCount;
    /// a user rule: (zeta in [-1, 1], weight), the weights summing to 2 as the built-in rules'
    std::vector<std::pair<Real, Real>> thickness_user_points{};
    /// rigid materials: the body's share from this section, given or computed from the solid
    /// its closed surface encloses (`inertia: enclosed`); its elements then add no mass of
    /// their own, and their thickness may be 0 (the contact surface of a solid)
    bool has_inertia = false;
    RigidInertia inertia{};
    /// non-structural mass per unit area (`area_mass`, LS-DYNA's MAREA): lumped on the
    /// particles by area as point masses (Model::point_masses)
    Real area_mass = 0;
};

/// Acceleration: the velocity steps by dt_n a(t_n) from the one before (the central difference
/// with the acceleration given instead of the forces; LS-DYNA's VAD 1).
enum class PrescribedKind { None, Displacement, Velocity, AngularVelocity, Acceleration };

/// One entry of `boundary`. Fixed degrees of freedom are global: ux uy uz rx ry rz.
/// `symmetry: x` becomes fixed = {ux, ry, rz}; `fix: all` = all six.
struct BoundaryCondition {
    std::vector<Index> nodes;
    std::array<bool, 6> fixed{};  ///< ux, uy, uz, rx, ry, rz
    PrescribedKind prescribed = PrescribedKind::None;
    Vec3 value = Vec3::Zero();  ///< displacement, velocity or angular velocity, times the curve
    Index curve = -1;           ///< index into Model::curves; -1 = factor 1 at all times
    /// the prescribed translation components (x, y, z); the others stay free (a prescribed
    /// angular velocity takes all three, but on a rigid body its rotation axes x, y, z)
    std::array<bool, 3> components{true, true, true};
    /// `rigid_body`: the elements (of rigid materials) whose rigid body the entry holds or
    /// drives, in its velocity at the centre of mass and its angular velocity, global axes
    /// (theory.md eq. 6.11-7); `nodes` is then empty
    std::vector<Index> rigid_elements{};
};

enum class LoadType { Pressure, Force, Moment, Gravity };

/// One entry of `loads`. Pressure acts on elements (follower, positive pushes against the
/// element normal); force and moment act on each node of the set (global components); gravity
/// gives each of its particles its mass times an acceleration (theory.md eq. 6.7-4).
struct Load {
    LoadType type = LoadType::Force;
    std::vector<Index> nodes;     ///< force, moment, gravity (its particles, ascending)
    std::vector<Index> elements;  ///< pressure
    Real pressure = 0;            ///< pressure value
    Vec3 vector = Vec3::Zero();   ///< force or moment value per node; gravity's acceleration
    Index curve = -1;             ///< -1 = factor 1 at all times
};

/// Masses lumped on particles (§6.1), without rotary inertia of their own: an entry of `masses`
/// (LS-DYNA's *ELEMENT_MASS, _NODE_SET, _PART) or a section's `area_mass` (*SECTION_SHELL's
/// MAREA), each particle of `nodes` gaining its `masses` entry.
struct PointMass {
    std::vector<Index> nodes;
    std::vector<Real> masses;  ///< per particle of `nodes`
};

/// One entry of `initial_conditions`.
struct InitialVelocity {
    std::vector<Index> nodes;
    Vec3 velocity = Vec3::Zero();
    Vec3 angular_velocity = Vec3::Zero();
    /// speed along each particle's initial surface normal (the normal of the element node
    /// order), added to velocity; negative = against the normal
    Real normal_velocity = 0;
    /// a rigid rotation about the axis through spin_centre: spin x (x - spin_centre) added to
    /// the velocity, and spin the particles' angular velocity (LS-DYNA's OMEGA of
    /// *INITIAL_VELOCITY_GENERATION)
    Vec3 spin = Vec3::Zero();
    Vec3 spin_centre = Vec3::Zero();
    /// `centre: mass`: the axis passes through the centre of mass of the set's particles (a
    /// rigid body's spin about its centre, LS-DYNA's *INITIAL_VELOCITY_RIGID_BODY VXR..VZR)
    bool spin_about_mass_centre = false;
};

/// Rayleigh damping (theory.md §6.5): a_m (1/s) on mass, a_s (s) on stiffness.
struct Damping {
    Real mass = 0;
    Real stiffness = 0;
};

enum class SolutionMode { Dynamic, Relaxation };
enum class BendingKernel { Bciz, Dkt };
enum class MembraneKernel { Cst, Smoothed };
/// How a triangle shares its rotary inertia among its corners (theory.md §6.2):
/// Belytschko (Kennedy, Belytschko & Lin 1986), Abaqus/Explicit, OpenRadioss.
enum class RotaryInertia { Belytschko, Abaqus, Radioss };

/// control.mass_scaling (theory.md §6.10, LS-DYNA DT2MS < 0, OpenRadioss /DT/NODA/CST): the
/// elements whose step is below time_step get added mass and inertia at set-up.
struct MassScaling {
    Real time_step = 0;            ///< the target step of the run (0: no mass scaling)
    Real added_mass_limit = 0.05;  ///< a warning past this fraction of a section's mass
    /// also the elements whose step falls below the target during the run (LS-DYNA's MS1ST 0);
    /// false: at set-up only, the step may then fall below the target (MS1ST 1)
    bool during_run = true;
};

/// control.minimum_time_step (LS-DYNA's *CONTROL_TERMINATION DTMIN with *CONTROL_TIMESTEP
/// ERODE): a floor on the stable step, `factor` times the run's first step or `time_step`
/// itself; with `erode` the elements whose step falls below it erode (theory.md §7.6), without
/// it the run stops there.
struct MinimumTimeStep {
    Real factor = 0;     ///< of the first step (0: not given)
    Real time_step = 0;  ///< the floor itself (0: not given)
    bool erode = false;
    [[nodiscard]] bool active() const { return factor > 0 || time_step > 0; }
};

struct Control {
    Real end_time = 0;
    Real time_step_scale = 0.9;
    SolutionMode mode = SolutionMode::Dynamic;
    Real tolerance = 1e-5;  ///< relaxation convergence: residual <= tolerance * |external force|
    // DKT by default: it passes the patch test on every mesh and follows large rotations;
    // BCIZ (the paper's element) passes only on three-line-family meshes (docs/validation.md).
    BendingKernel bending = BendingKernel::Dkt;
    /// CST (theory.md §3) or the CST strains smoothed over the neighbours (membrane_smoothing.hpp)
    MembraneKernel membrane = MembraneKernel::Cst;
    Real energy_error_limit = 0.5;  ///< dynamic runs stop (exit 1) past this relative error
    long max_relaxation_iterations = 200000;  ///< per load level
    /// theory.md §3.4: thickness follows the plane-stress condition (off by default, like
    /// LS-DYNA's ISTUPD = 0; needed for large membrane strains)
    bool thickness_update = false;
    /// control.end_when_body_stops: the run ends once this rigid body has stopped, i.e. its
    /// velocity along its initial velocity is no longer positive (-1: run to end_time only)
    Index end_body = -1;
    RotaryInertia rotary_inertia = RotaryInertia::Belytschko;
    MassScaling mass_scaling;
    MinimumTimeStep minimum_time_step;
};

/// One entry of `rigid_bodies`: a rigid impactor with a plane face (theory.md §8.3). It moves
/// by the contact forces it receives; a `fixed` body has infinite mass and keeps its velocity.
enum class RigidShape { Plane, Sphere, Cylinder };

/// A rigid body: a face the shell's particles stay outside of (theory.md §8.3), moving in
/// translation. Its geometry at t = 0 (model/rigid_face.hpp).
struct RigidBody {
    std::string name;
    Real mass = 0;       ///< 0 when fixed
    bool fixed = false;  ///< infinite mass: moves at `velocity` whatever it meets
    RigidShape shape = RigidShape::Plane;
    /// plane: a point of the face (a corner of a finite one); sphere: the centre; cylinder: a
    /// point of the axis (the end of a finite one)
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ();   ///< plane: unit normal of the face, pointing towards the shell
    Vec3 velocity = Vec3::Zero();  ///< initial velocity
    Real radius = 0;               ///< sphere, cylinder
    Vec3 axis = Vec3::UnitZ();     ///< cylinder: unit axis, from `point`
    Real length = 0;               ///< cylinder: length along the axis; 0 = infinite
    /// plane: a finite face, `size_l` along the unit `edge` (in the face) from `point` and
    /// `size_m` along normal x edge; 0 = infinite
    Vec3 edge = Vec3::UnitX();
    Real size_l = 0, size_m = 0;
};

/// One entry of `constraints` of type rigid: particles that move as one rigid body (LS-DYNA's
/// nodal rigid bodies and spot welds; solver/nodal_rigid_bodies.hpp).
struct NodalRigidBody {
    std::vector<Index> nodes;  ///< at least two, sorted
    /// A spot weld's failure (LS-DYNA's *CONSTRAINED_SPOTWELD SN, SS, N, M, TF; theory.md eq.
    /// 6.11-13): a group of two particles lets go for good once (f_n / normal_force)^
    /// normal_exponent + (f_s / shear_force)^shear_exponent >= 1, f_n the tension and f_s the
    /// shear its constraint carries, or once the time reaches `time`, or once the plastic
    /// strain of the sheets at one of its particles reaches `plastic_strain` (LS-DYNA's EP,
    /// EPSF; eq. 6.11-15). 0 forces leave their term out; without any the group never lets go.
    struct Failure {
        Real normal_force = 0, shear_force = 0;
        Real normal_exponent = 2, shear_exponent = 2;
        Real time = std::numeric_limits<Real>::infinity();
        Real plastic_strain = std::numeric_limits<Real>::infinity();
    };
    Failure failure;
    [[nodiscard]] bool can_fail() const {
        return failure.normal_force > 0 || failure.shear_force > 0 ||
               failure.time < std::numeric_limits<Real>::infinity() || fails_by_plastic_strain();
    }
    [[nodiscard]] bool fails_by_plastic_strain() const {
        return failure.plastic_strain < std::numeric_limits<Real>::infinity();
    }
};

/// One entry of `constraints` of type tied: each particle of `nodes` stays at its initial place
/// relative to the closest face of `elements` within `tolerance` (LS-DYNA's *CONTACT_TIED_*;
/// solver/tied_surfaces.hpp, theory.md §6.12).
struct TiedSurface {
    std::vector<Index> nodes;     ///< the tied particles (slaves), sorted
    std::vector<Index> elements;  ///< the faces they are tied to (masters), sorted
    Real tolerance = 0;           ///< largest distance to a face; 0: each pair's larger thickness
    /// tiebreak (LS-DYNA's *CONTACT_TIEBREAK_NODES_TO_SURFACE NFLF, SFLF, NEN, MES): a tie lets
    /// go for good once (f_n / normal_force)^normal_exponent + (f_s / shear_force)^shear_exponent
    /// >= 1, f_n its force in tension and f_s in shear (eq. 6.12-2); 0 forces: it never does
    Real normal_force = 0, shear_force = 0;
    Real normal_exponent = 2, shear_exponent = 2;
    /// or by stresses (LS-DYNA's *CONTACT_TIEBREAK_SURFACE_TO_SURFACE NFLS, SFLS): each tie's
    /// forces are these times its slave's area, a third of its triangles' (eq. 6.12-3)
    Real normal_stress = 0, shear_stress = 0;
};

enum class ContactType { Self, Rigid };
enum class ContactMethod { LagrangeMultiplier, Penalty };

/// One entry of `contact`. Self: every particle of the elements against every triangle of
/// them (both faces, thickness offsets). Rigid: the particles of `nodes` against a body.
struct ContactDefinition {
    ContactType type = ContactType::Self;
    ContactMethod method = ContactMethod::LagrangeMultiplier;
    std::vector<Index> elements;  ///< self: the faces (and, without `nodes`, their particles)
    /// rigid: the particles; self: the particles that touch `elements`' faces (LS-DYNA's
    /// NODES_TO_SURFACE with a node set), empty: the particles of `elements`
    std::vector<Index> nodes;
    Index body = -1;  ///< rigid: index into Model::rigid_bodies
    /// self: pairs whose initial distance is below it are never in contact (0 = automatic,
    /// 1.5 x the largest thickness; theory.md R8)
    Real exclusion_radius = 0;
    Real penalty_scale = 0.1;  ///< penalty: stiffness = scale x pair mass / dt^2
    int max_iterations = 50;   ///< Lagrange multipliers: Gauss-Seidel sweeps per step
    /// Lagrange multipliers: Coulomb friction coefficient between the particles and the body or
    /// the faces they touch (theory.md §8.4); 0 frictionless, infinity: no sliding once in
    /// contact. With a decay, the static coefficient mu_s of
    /// mu = mu_d + (mu_s - mu_d) exp(-decay |v_rel|) (LS-DYNA's FS, FD, DC; eq. 8.4-5)
    Real friction = 0;
    Real friction_dynamic = 0;  ///< mu_d (used only with friction_decay > 0)
    Real friction_decay = 0;    ///< DC, in time per length (s/m in SI); 0: mu = friction
    /// rigid: the distance from the face at which a particle touches it; negative: half the
    /// particle's shell thickness (theory.md §8.3). LS-DYNA's rigid walls: 0 (the node itself)
    Real offset = -1;
};

enum class Quantity {
    Ux,
    Uy,
    Uz,
    Umag,
    Vx,
    Vy,
    Vz,
    Ax,
    Ay,
    Az,
    Rx,
    Ry,
    Rz,
    ReactionX,
    ReactionY,
    ReactionZ,
    ReactionMx,
    ReactionMy,
    ReactionMz,
    ForceX,
    ForceY,
    ForceZ,
    /// the external force against the particle's normal over its area: the pressure its faces
    /// take (a blast's, a pressure load's)
    Pressure,
    // rigid bodies (rigid_<name>_<quantity>): displacement, velocity, acceleration, contact force
    RigidUx,
    RigidUy,
    RigidUz,
    RigidVx,
    RigidVy,
    RigidVz,
    RigidAx,
    RigidAy,
    RigidAz,
    RigidForceX,
    RigidForceY,
    RigidForceZ,
    // contact definitions (contact_<n>_force_<x|y|z>): the contact force on their slaves
    ContactForceX,
    ContactForceY,
    ContactForceZ,
    // the whole model (theory.md §7.6): elements eroded so far
    ErodedElements
};
/// How a history reduces its set: MassMean weighs each particle by its mass (for velocities, the
/// set's momentum over its mass: LS-DYNA's MATSUM rigid-body velocity of a part).
enum class Reduce { Single, Sum, Max, Min, Mean, MassMean };

struct HistoryRequest {
    std::string name;
    std::vector<Index> nodes;  ///< empty for rigid-body quantities
    Index body = -1;           ///< rigid-body quantities: index into Model::rigid_bodies
    Index contact = -1;        ///< contact quantities: index into Model::contacts
    bool model_wide = false;   ///< a quantity of the whole model (eroded_elements)
    Quantity quantity = Quantity::Uz;
    Reduce reduce = Reduce::Single;  ///< Single only when the set has one node
};

/// How the arrays of the VTU frames are stored (io/vtu_writer.hpp).
enum class FieldsEncoding { Raw, Base64, Ascii };

struct OutputControl {
    Real every = 0;         ///< history sampling interval (0 = every step)
    Real fields_every = 0;  ///< VTU frame interval (0 = first and last only)
    FieldsEncoding fields_encoding = FieldsEncoding::Raw;
    bool fields_zlib = false;  ///< zlib-compressed arrays (raw encoding only)
    std::vector<HistoryRequest> histories;
};

/// The whole validated model.
struct Model {
    std::string title;
    std::string source_file;  ///< path of the YAML file, for messages
    /// What the reader of a keyword deck ignored or mapped approximately, one sentence each
    /// (io/lsdyna_deck.hpp); printed by `check` and at the start of a run
    std::vector<std::string> notes;

    std::vector<Vec3> nodes;                      ///< initial particle positions
    std::vector<std::array<Index, 3>> triangles;  ///< counter-clockwise about the normal
    /// After particle separations (theory.md §7.7, model/separated_model.hpp): per particle,
    /// the particle of the model as read that it was split from (itself where it was read);
    /// empty before any
    std::vector<Index> separated_from;
    std::map<std::string, std::vector<Index>> node_sets;     ///< sorted, unique; has "all"
    std::map<std::string, std::vector<Index>> element_sets;  ///< sorted, unique; has "all"

    std::vector<Material> materials;
    std::vector<Section> sections;
    std::vector<Index> element_section;  ///< section index of every triangle

    std::vector<Curve> curves;
    std::vector<BoundaryCondition> boundary;
    std::vector<Load> loads;
    std::vector<BlastLoad> blast_loads;  ///< the `loads` of type blast, in their order
    std::vector<InitialVelocity> initial_conditions;
    std::vector<PointMass> point_masses;  ///< `masses`, in their order
    std::vector<RigidBody> rigid_bodies;
    std::vector<NodalRigidBody> nodal_rigid_bodies;  ///< `constraints` of type rigid
    std::vector<TiedSurface> tied_surfaces;          ///< `constraints` of type tied
    std::vector<ContactDefinition> contacts;
    Damping damping;
    Control control;
    OutputControl output;

    [[nodiscard]] Index n_particles() const { return static_cast<Index>(nodes.size()); }
    [[nodiscard]] Index n_elements() const { return static_cast<Index>(triangles.size()); }
};

}  // namespace fpmshell
