// Floating-point operations and bytes of one element-step, counted by hand from the source
// (this machine has no hardware floating-point counters): the figure of merit of the table of
// perf_table.cpp divides them by the measured time. Accuracy about +-20 %.
//
// Flop rules: every add, subtract, multiply, divide and square root counts 1 (a divide or a
// square root takes several times the issue slot of a multiply: the fraction of the peak
// understates how busy the divider is); negations, comparisons, min/max, abs and copies count 0.
// A transcendental call (log, pow: the Johnson-Cook law) counts k_transcendental, about the
// polynomial it evaluates. Eigen fixed-size products as written: 3x3 * 3x3 = 27 mul + 18 add = 45,
// 3x3 * 3 = 9 mul + 6 add = 15, 3x6 * 6 = 18 mul + 15 add = 33, 6x3 * 3 = 30, cross = 6 mul +
// 3 sub = 9, dot(3) = 5, squaredNorm(3) = 5, norm(3) = 6, normalized(3) = 6 + 3 div = 9,
// scalar * Vec3 = 3, Vec3 +- Vec3 = 3.
//
// Bytes: what one element-step must move between the cores and memory if every array streams
// once per step (the compulsory traffic): each particle's data once (not once per element that
// gathers it: a particle is shared by about 6 triangles), every material point read and written
// back whole (88 B: the fields share cache lines, so even the elastic update, which touches the
// stress only, drags the whole struct), the element's slots written then gathered, per-element
// outputs. Write-allocate reads are not counted (STREAM convention, like the bandwidth peak).
// Meshes whose arrays fit the caches (10^3 and 10^4 elements; the elastic 10^5 plate, ~60 MB,
// on the 300 MiB L3 this VM reports) move far less than this to memory: their GB/s is the rate
// at which the kernel touches that data.
//
// Cross-check (valgrind --tool=lackey --detailed-counts=yes, 968-element plate, difference of
// runs with and without 10 more calls, same working tree): the element loop executes ~2 450
// vector-register ALU operations per elastic element (scalar SSE2 doubles, packed doubles
// counted once, shuffles, sign flips, compares) against 2 567 flops counted here, and ~9 200 per
// plastic 5x3 element against 8 024 (4 Newton evaluations) or 5 639 (one); the whole elastic
// step ~2 690 against 2 790.
#pragma once

#include "fpmshell/materials/material_point.hpp"
#include "fpmshell/model/model.hpp"

namespace fpmshell::bench::cost {

inline constexpr double k_transcendental = 20;  // log: ~20 flop of polynomial (pow: 2)

// ---- element loop (ShellElements::compute), per element -----------------------------------

// The path element (elements/path_element.hpp) with the small-angle series of its rotations
// (every step of a stable run):
//   a2, a3, r2, r3                      4 Vec3 sub                                  12
//   na_raw, n_raw                       2 cross                                      18
//   lmax2                               3 squaredNorm + (a3 - a2)                    18
//   degeneracy test                     2 norm + 2 mul                               14
//   na, n                               2 normalized                                 18
//   area, area_ratio, normal_cosine     norm + mul, 2 norm + div, dot                25
//   minimal_rotation (closed form)      cross 9, dot 5, f 2, d 7, f x y.. 6, 9 entries 15  44
//   r2p, r3p                            2 x (3x3^T * 3)                              30
//   theta_ip                            cross 9 + 2 dot 10, small_angle_atan2 10     29
//   r_ip = rotation_matrix(theta na)    3 mul + rotation_matrix                      53
//   r2pp, r3pp                          2 x (3x3^T * 3)                              30
//   ex, ey                              normalized + cross                           18
//   x2, x3, y3                          norm + 2 dot                                 16
//   u2, u3                              2 x (Vec3 sub + 3x3 * 3)                     36
//   r_r                                 3x3 * 3x3                                    45
//   omega_r = rotation_vector(r_r)      series branch                                23
//   3 x drill-axis term (eq. 2.6c)      sub 3, dot 5, mul 1, scale 3, add 3          45
//   3 x phi_i                           rotation_matrix 50 + 3x3^T*3x3 45 +
//                                       rotation_vector 23 + 2 rows of T_a phi 10   384
//   frame_current                       3x3 * 3x3^T                                  45
// rotation_matrix_series (core/rotation.hpp): |phi|^2 5, a and b series 2 x 8, d 2, b x y.. 6,
// diagonal 3 x 3, off-diagonal 6 x 2 = 50. rotation_vector_series: trace 4, w 3, s2 6,
// series 7 + 3 = 23. atan_series with its bound test: test 1, t 1, t^2 1, series 7.
inline constexpr double k_reverse_motion = 903;

// The rest of compute() per element: characteristic_length from the path element's current
// 2A (3 edge squaredNorms with their subs 24, 2 max, sqrt, div) = 28; element_dt + drift test
// 4; phase 2 gathers the 3 corner slots into their particles (3 x (f 3 + m 3 adds)) = 18; the
// totals 3.
inline constexpr double k_element_rest = 28 + 4 + 18 + 3;

// local_triangle_loads (elastic_triangle_block.hpp), per element outside the point loops:
//   1 / 2A 2; cst_gradients 7; dkt_sides: 3 sides x (xij, yij 1, l2 3, 1 / l2 2, cb 3,
//   cc 5, ce 5) + the shared division 3 = 60; d_eps_m = cst_strain 11 (u_1 = 0, b_3 = 0);
//   h, thickness factor 4; the curvature matrix at the 3 corners (below) and kappa_i = B_i theta
//   3 x 33 = 99; f_m = cst_nodal_forces 18; m_b = sum_i B_i^T M_i 3 x 30 + 12 = 102;
//   out-of-plane forces and the drilling couple (eq. 4.6a-c) 20; forward rotation of 6 vectors
//   6 x 15 = 90.
inline constexpr double k_loads_element = 2 + 7 + 11 + 4 + 99 + 18 + 102 + 20 + 90;
inline constexpr double k_dkt_shape = 60;

// The curvature matrix at one corner (3 per element). dkt_curvature (dkt_curvature.hpp; N,xi
// and N,eta are constants at a corner): Hx, Hy on both, rotation columns only, 2 x 42 = 84;
// the 3x6 matrix: 6 columns x (2 + 4 + 6) = 72.
inline constexpr double k_bending_dkt = 84 + 72;
// bending_b_bciz: f 2; 3 bubble terms x 14 = 42; 3 corners x (6 q_g x 9 + 2 columns x (hb 2 +
// 6 + 6 + 7)) = 3 x 96 = 288.
inline constexpr double k_bending_bciz = 2 + 42 + 288;

// Per in-plane point: d_kappa from the corner curvatures 15; after the thickness loop: N, M
// averages 12, wa 1, sum A w N 6, resultant 6, corner moments 3 x (1 + 6) 21, strain / plastic
// work 6 = 67 (no stiffness damping).
inline constexpr double k_inplane_point = 15 + 12 + 1 + 6 + 6 + 21 + 6;

// Per material point besides the material update: z 1, d_eps = d_eps_m + z d_kappa 6, wz 1,
// plastic work 3, thickness strain 10, n += wz sigma 6, m += (wz z) sigma 7, work 11.
inline constexpr double k_material_point = 45;

// LinearElastic::update: sigma += C d_eps, 15 + 3.
inline constexpr double k_elastic_update = 18;

// The return mapping (materials/j2/j2_return_mapping.hpp, j2_consistency.hpp), bilinear flow
// curve, no rate factor:
//   trial (sigma_n + C d_eps 18, xi 3, kappa 1, kappa^2 / 3 2, p_norm2 10 + 2, test 1)   37
//   constants of the return (h_k 3, s, d 2, A1 2, A2 5, a1 5, a2 3, f_bar_tr 2, a_bar 4,
//   bound of dgamma 5, Phi'(0) 8, Phi''(0) 9, Halley step 10) 58, the update (s, d 2,
//   xi 5, back stress 8, stress 3, alpha 3, P xi 7, plastic work 13) 41                 99
//   per evaluation of Phi (q1, q2 5, c1, c2 4, f_bar 2, f_bar f_bar' 5, alpha 3,
//   f_bar alpha' 4, flow curve 2, kappa 4, g 2, F 4, Phi 4, Phi' 9, Phi'' 25) with its
//   test and bracketed Halley step (12)                                                 85
// Evaluations: J2Return::evaluations on the plate of bench/crash_kernels (every point
// yielding, trial overshoot about 10 % of the yield radius): 2 on nearly every pack of 8.
// A Johnson-Cook evaluation adds a power (vector_log and vector_exp, core/simd_math.hpp).
inline constexpr double k_j2_trial = 37;
inline constexpr double k_j2_return = 99;
inline constexpr double k_j2_newton_evaluation = 85;
inline constexpr int k_j2_newton_evaluations_plate = 2;
// The square tube (Johnson-Cook, trial overshoots of a few per cent in a crash): 3 assumed.
inline constexpr int k_j2_newton_evaluations_tube = 3;
// Johnson-Cook flow curve and rate factor (the square tube): the filtered effective strain
// rate (11 + 3) and the rate factor (div, log, 2) at every point; a pow (a log and an exp)
// per flow-curve evaluation of the return (one per Newton evaluation).
inline constexpr double k_j2_rate = 14 + 3 + k_transcendental;
inline constexpr double k_j2_johnson_cook_evaluation = 2 * k_transcendental;

struct MaterialCost {
    bool plastic = false;
    double yield_fraction = 1;  ///< share of the points taking the return mapping
    int newton_evaluations = k_j2_newton_evaluations_plate;
    bool rate = false;          ///< rate factor active (Johnson-Cook C > 0 or Cowper-Symonds)
    bool johnson_cook = false;  ///< pow in the flow curve
};

inline double j2_return_flops(const MaterialCost& m) {
    return k_j2_return +
           m.newton_evaluations *
               (k_j2_newton_evaluation + (m.johnson_cook ? k_j2_johnson_cook_evaluation : 0.0));
}

inline double material_update_flops(const MaterialCost& m) {
    if (!m.plastic) return k_elastic_update;
    return k_j2_trial + (m.rate ? k_j2_rate : 0.0) + m.yield_fraction * j2_return_flops(m);
}

/// Flops of ShellElements::compute per element: n_inplane x n_thickness points.
inline double element_loop_flops(int n_inplane, int n_thickness, BendingKernel bending,
                                 const MaterialCost& m) {
    const double b =
        bending == BendingKernel::Dkt ? k_dkt_shape + 3 * k_bending_dkt : 3 * k_bending_bciz;
    return k_reverse_motion + k_element_rest + k_loads_element + b + n_inplane * k_inplane_point +
           n_inplane * n_thickness * (k_material_point + material_update_flops(m));
}

// Bytes of ShellElements::compute, per element: connectivity 12, section 4, point offset 8,
// thickness 8, bend_ratio and bend_lc 16, element dt 8 written; the 3 corner slots of force and
// moment written (144) and read back by the gather (144) with their CSR indices (12); failure
// flag 1 + 1, work / damping / plastic work 24 written, those and dt read by the totals 32;
// membrane force and bending moment 48 written.
inline constexpr double k_element_loop_bytes_per_element =
    12 + 4 + 8 + 8 + 16 + 8 + 144 + 144 + 12 + 2 + 24 + 32 + 48;
// Per particle: x_prev, x, dtheta, drill_axis gathered 96, CSR begin 4, f_int and m_int written 48.
inline constexpr double k_element_loop_bytes_per_particle = 96 + 4 + 48;
// Per material point: the whole MaterialPoint read and written back.
inline constexpr double k_bytes_per_material_point = 2.0 * sizeof(MaterialPoint);

inline double element_loop_bytes(int n_points, double particles_per_element) {
    return k_element_loop_bytes_per_element +
           particles_per_element * k_element_loop_bytes_per_particle +
           n_points * k_bytes_per_material_point;
}

// ---- the rest of the step (ExplicitSolver::cycle), explicit_solver.cpp ---------------------

// Per element: the cross product for the normals (2 Vec3 sub + cross) 15 and its 3 gathers into
// the corner particles (3 x 3 adds) 9; a pressure load gathers it again, f += s cr (3 x 6) 18.
inline constexpr double k_step_flops_per_element = 15 + 9;
inline constexpr double k_step_pressure_flops_per_element = 18;
// Per particle: normal (norm, 3 div) 9; central difference for translations (force 6,
// v_new 13, reaction 8, residual sums 6 + 15) and rotations (moment 3, tangent projections of
// moment and omega 2 x 11, w_free 13, 2 remove_components along the normal 2 x 20, reaction
// moment 8, residual sums 1 + 7 + 16) = 158; energies (kinetic 15, external and reaction work
// 39) 54, + contact work 15; positions x 6, dtheta 3, rotation = R(dtheta) R 50 + 45;
// finiteness check 9.
inline constexpr double k_step_flops_per_particle = 9 + 158 + 54 + 104 + 9;
inline constexpr double k_step_contact_flops_per_particle = 15;

// Bytes per particle: normal 24 + CSR 4; f_ext, m_ext zeroed 48; central difference reads
// f_ext f_int f_contact v m_ext m_int normal omega (192), mass inertia 16, 9 flag bytes, writes
// v_prev v reaction omega_prev omega reaction_moment (144); energies read 15 Vec3 + 2 Real (376)
// and write the 4 *_prev vectors (96); positions read x v omega rotation (144) and write
// x_prev x dtheta rotation (144); finiteness check reads x omega f_int (72).
inline constexpr double k_step_bytes_per_particle =
    28 + 48 + (192 + 16 + 9 + 144) + (376 + 96) + 288 + 72;
// Pressure: loaded-particle index and CSR 8, f_ext read and written 48. Contact: f_contact
// copied to f_contact_prev and zeroed (72), both read for the contact work (48).
inline constexpr double k_step_pressure_bytes_per_particle = 8 + 48;
inline constexpr double k_step_contact_bytes_per_particle = 72 + 48;
// Per element: cross product written 24 and gathered 24, particle -> element CSR 12;
// pressure: its element list 12 and the cross product again 24.
inline constexpr double k_step_bytes_per_element = 24 + 24 + 12;
inline constexpr double k_step_pressure_bytes_per_element = 12 + 24;

struct StepExtras {
    bool pressure = false;
    bool contact = false;  ///< the contact solver itself (search, multipliers) is NOT counted
};

inline double step_rest_flops(double particles_per_element, const StepExtras& x) {
    return k_step_flops_per_element + (x.pressure ? k_step_pressure_flops_per_element : 0.0) +
           particles_per_element *
               (k_step_flops_per_particle + (x.contact ? k_step_contact_flops_per_particle : 0.0));
}

inline double step_rest_bytes(double particles_per_element, const StepExtras& x) {
    return k_step_bytes_per_element + (x.pressure ? k_step_pressure_bytes_per_element : 0.0) +
           particles_per_element * (k_step_bytes_per_particle +
                                    (x.pressure ? k_step_pressure_bytes_per_particle : 0.0) +
                                    (x.contact ? k_step_contact_bytes_per_particle : 0.0));
}

}  // namespace fpmshell::bench::cost
