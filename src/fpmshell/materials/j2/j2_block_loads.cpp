#include "fpmshell/materials/j2/j2_block_loads.hpp"

namespace fpmshell {

namespace {
/// Points whose iterations run in lockstep (j2_return_mapping_points): enough independent
/// chains of divisions and square roots to hide their latency.
constexpr std::size_t k_lockstep_points = 4;

/// The block's loads; with Fades, its points' stress faded by their damage (eq. 7.6-6): a
/// variant of its own, so that the kernel without fading keeps its code and its bits.
template <bool Fades>
ElasticTriangleLoads<RealPack> j2_block_loads(const J2Plastic& material, const BlockStep& step) {
    using namespace block_points_detail;
    using J2 = J2Plastic;
    const std::size_t n_points = step.n_points;
    auto field = [&](std::size_t p, std::size_t f) -> RealPack& {
        return step.state[f * n_points + p];
    };
    // isotropic hardening (beta = 1): the back stress stays zero and is neither read nor written
    const bool kinematic = material.return_constants().beta != 1.0;
    // No software prefetch of the next block here, unlike the elastic blocks: a plastic block
    // computes long enough for the hardware prefetcher to stream the next one, and the 60 to 120
    // prefetched lines of its fields stalled on full fill buffers (perf: two thirds of this
    // function's samples in the paper tube's folding phase; without them that phase runs 4 %
    // faster on two threads, the crash kernels 1-2 % faster).

    std::array<RealPack, 3 * k_max_block_points> stress;
    for (std::size_t p = 0; p < n_points; ++p)
        for (std::size_t r = 0; r < 3; ++r) stress[3 * p + r] = field(p, J2::k_stress + r);
    // the yield surfaces of the points, kappa_n = flow radius at alpha_n (§7.3)
    std::array<RealPack, 3 * k_max_block_points> back_stress;
    std::array<RealPack, k_max_block_points> third_k2, strain_rate, new_strain_rate, plastic_strain;
    YieldSurfaces<RealPack> yield{back_stress.data(), third_k2.data(), J2::k_yield_tolerance};
    // eq. 7.4-2: the thermal factor of each point at its temperature of the step's start, on
    // the yield radius of the check and, with R, on the return's (1 without thermal softening)
    const ThermalSoftening& thermal = material.thermal_softening();
    std::array<RealPack, k_max_block_points> theta;
    for (std::size_t p = 0; p < n_points; ++p) {
        for (std::size_t r = 0; r < 3; ++r)
            back_stress[3 * p + r] = kinematic ? field(p, J2::k_back_stress + r) : RealPack(0.0);
        RealPack kappa = field(
            p, J2::k_flow_radius);  // sigma_f(0) before the first yield (J2Plastic::write_point)
        if (thermal.active) {
            theta[p] = thermal.factor(field(p, J2::k_plastic_work));
            kappa *= theta[p];
        }
        third_k2[p] = kappa * kappa * (1.0 / 3.0);
    }
    auto softened = [&](const RealPack& r, std::size_t p) {
        return thermal.active ? r * theta[p] : r;
    };
    if (material.rate_dependent()) {
        yield.rate = &material.rate_factor();
        yield.strain_rate = strain_rate.data();
        yield.new_strain_rate = new_strain_rate.data();
        yield.dt = step.dt;
        yield.rate_filter = J2::k_rate_filter;
        for (std::size_t p = 0; p < n_points; ++p) strain_rate[p] = field(p, J2::k_strain_rate);
        if (material.rate_factor().selects_curve()) {
            yield.table = &material.return_constants().flow.table;
            yield.plastic_strain = plastic_strain.data();
            for (std::size_t p = 0; p < n_points; ++p)
                plastic_strain[p] = field(p, J2::k_plastic_strain);
        }
    }
    // The yielding points: the return mapping of §7.3 on the yielding (point, lane) pairs of
    // the block, in place in the block's state (a lane that takes this path never falls back,
    // so its old state is not needed again). A point that yields on most lanes runs on its own
    // packs, masked; the pairs of the other points are packed densely, k_lanes pairs at a time
    // (the pairs of a block that yields in part fill whole packs). A lane's result does not
    // depend on its pack: the iteration is masked lane by lane.
    auto return_mapping = [&](std::size_t n_pts, const RealPack::mask_type* yielding,
                              const std::array<RealPack, 3>* d_eps, const RealPack* rate_factor,
                              RealPack* new_stress, RealPack* d_plastic_work) {
        const J2ReturnConstants& constants = material.return_constants();
        // Points on their own packs, k_lockstep_points at a time (their Newton iterations in
        // lockstep, materials/j2_consistency.hpp), the old state straight from the block's fields.
        auto old_state = [&](std::size_t p) {
            const RealPack zero(0.0);
            return J2PointState<RealPack>{
                {field(p, J2::k_stress), field(p, J2::k_stress + 1), field(p, J2::k_stress + 2)},
                {kinematic ? field(p, J2::k_back_stress) : zero,
                 kinematic ? field(p, J2::k_back_stress + 1) : zero,
                 kinematic ? field(p, J2::k_back_stress + 2) : zero},
                field(p, J2::k_plastic_strain),
                field(p, J2::k_flow_radius),
                field(p, J2::k_flow_slope)};
        };
        auto store = [&](std::size_t p, const J2Return<RealPack>& ret) {
            const RealPack::mask_type& y = ret.yielded;  // not: inside after all (rounding)
            for (std::size_t r = 0; r < 3; ++r) {
                stdx::where(yielding[p], new_stress[3 * p + r]) = ret.state.stress[r];
                if (kinematic)
                    stdx::where(y, field(p, J2::k_back_stress + r)) = ret.state.back_stress[r];
            }
            stdx::where(y, d_plastic_work[p]) = ret.plastic_work;
            stdx::where(y, field(p, J2::k_plastic_strain)) = ret.state.plastic_strain;
            stdx::where(y, field(p, J2::k_plastic_work)) =
                field(p, J2::k_plastic_work) + ret.plastic_work;
            stdx::where(y, field(p, J2::k_flow_radius)) = ret.state.flow_radius;
            stdx::where(y, field(p, J2::k_flow_slope)) = ret.state.flow_slope;
        };
        // K points p[0..K) at once
        auto return_points = [&]<std::size_t K>(const std::size_t* p) {
            using j2_detail::array_of;
            const std::array<J2Return<RealPack>, K> ret = j2_return_mapping_points<RealPack, K>(
                constants, array_of<K>([&](std::size_t k) { return old_state(p[k]); }),
                array_of<K>([&](std::size_t k) { return d_eps[p[k]]; }),
                array_of<K>([&](std::size_t k) { return softened(rate_factor[p[k]], p[k]); }),
                array_of<K>([&](std::size_t k) { return yielding[p[k]]; }));
            for (std::size_t k = 0; k < K; ++k) store(p[k], ret[k]);
        };
        std::array<std::size_t, k_max_block_points> own;  // the points on their own packs
        std::size_t n_own = 0;
        constexpr int w = k_lanes;
        // the inputs of the batch, structure of arrays: stress 3, back stress 3, alpha, flow
        // radius, flow slope, strain increment 3, rate factor
        alignas(64) std::array<std::array<Real, w>, 13> in;
        std::array<std::size_t, w> batch_point;
        std::array<int, w> batch_lane;
        int n = 0;
        auto run_batch = [&] {
            for (int i = n; i < w; ++i)  // unused lanes compute on a copy of the first pair
                for (auto& input : in) input[static_cast<std::size_t>(i)] = input[0];
            auto pack = [&](std::size_t f) { return RealPack(in[f].data(), stdx::vector_aligned); };
            const J2PointState<RealPack> old{{pack(0), pack(1), pack(2)},
                                             {pack(3), pack(4), pack(5)},
                                             pack(6),
                                             pack(7),
                                             pack(8)};
            RealPack::mask_type used(false);
            for (int i = 0; i < n; ++i) used[static_cast<std::size_t>(i)] = true;
            const J2Return<RealPack> ret =
                j2_return_mapping(constants, old, {pack(9), pack(10), pack(11)}, pack(12), used);
            for (int i = 0; i < n; ++i) {
                const std::size_t p = batch_point[static_cast<std::size_t>(i)];
                const int l = batch_lane[static_cast<std::size_t>(i)];
                for (std::size_t r = 0; r < 3; ++r)
                    set_lane(new_stress[3 * p + r], l, lane(ret.state.stress[r], i));
                if (!lane(ret.yielded, i))
                    continue;  // inside after all (rounding): the trial state
                set_lane(d_plastic_work[p], l, lane(ret.plastic_work, i));
                if (kinematic)
                    for (std::size_t r = 0; r < 3; ++r)
                        set_lane(field(p, J2::k_back_stress + r), l,
                                 lane(ret.state.back_stress[r], i));
                set_lane(field(p, J2::k_plastic_strain), l, lane(ret.state.plastic_strain, i));
                set_lane(field(p, J2::k_plastic_work), l,
                         lane(field(p, J2::k_plastic_work), l) + lane(ret.plastic_work, i));
                set_lane(field(p, J2::k_flow_radius), l, lane(ret.state.flow_radius, i));
                set_lane(field(p, J2::k_flow_slope), l, lane(ret.state.flow_slope, i));
            }
            n = 0;
        };
        for (std::size_t p = 0; p < n_pts; ++p) {
            const int count = stdx::popcount(yielding[p]);
            if (count == 0) continue;
            if (2 * count > k_lanes) {
                own[n_own++] = p;
                continue;
            }
            for (int l = 0; l < k_lanes; ++l) {
                if (!lane(yielding[p], l)) continue;
                const auto i = static_cast<std::size_t>(n);
                for (std::size_t r = 0; r < 3; ++r) {
                    in[r][i] =
                        lane(field(p, J2::k_stress + r), l);  // the old stress: not stored yet
                    in[3 + r][i] = lane(back_stress[3 * p + r], l);
                    in[9 + r][i] = lane(d_eps[p][r], l);
                }
                in[6][i] = lane(field(p, J2::k_plastic_strain), l);
                in[7][i] = lane(field(p, J2::k_flow_radius), l);
                in[8][i] = lane(field(p, J2::k_flow_slope), l);
                in[12][i] = lane(softened(rate_factor[p], p), l);
                batch_point[i] = p;
                batch_lane[i] = l;
                if (++n == w) run_batch();
            }
        }
        if (n > 0) run_batch();
        std::size_t i = 0;
        for (; i + k_lockstep_points <= n_own; i += k_lockstep_points)
            return_points.template operator()<k_lockstep_points>(own.data() + i);
        switch (n_own - i) {
            case 3:
                return_points.template operator()<3>(own.data() + i);
                break;
            case 2:
                return_points.template operator()<2>(own.data() + i);
                break;
            case 1:
                return_points.template operator()<1>(own.data() + i);
                break;
            default:
                break;
        }
    };
    const ElasticTriangleLoads<RealPack> loads =
        elastic_triangle_loads<RealPack, decltype(return_mapping), Fades>(
            *step.motion, *step.constants, step.thickness, stress.data(), step.viscous_rate, &yield,
            return_mapping, step.fading);
    // the new stresses and filtered rates of the valid lanes
    store_stress(step, loads.valid, stress.data(), J2::k_stress);
    if (yield.new_strain_rate)
        for (std::size_t p = 0; p < n_points; ++p)
            stdx::where(loads.valid, field(p, J2::k_strain_rate)) = new_strain_rate[p];
    return loads;
}

}  // namespace

ElasticTriangleLoads<RealPack> block_point_loads(const J2Plastic& material, const BlockStep& step) {
    return step.fading ? j2_block_loads<true>(material, step)
                       : j2_block_loads<false>(material, step);
}

}  // namespace fpmshell
