#include "fpmshell/contact/bucket_grid.hpp"

#include <algorithm>
#include <cmath>

namespace fpmshell {

std::int64_t BucketGrid::clamp_axis(Real coordinate, int axis) const {
    const std::int64_t n = axis == 0 ? nx_ : axis == 1 ? ny_ : nz_;
    const auto i = static_cast<std::int64_t>(std::floor((coordinate - origin_[axis]) / cell_));
    return std::clamp<std::int64_t>(i, 0, n - 1);
}

std::int64_t BucketGrid::bucket_of(const Vec3& p) const {
    if (nx_ == 0) return -1;
    std::int64_t idx[3];
    const std::int64_t n[3] = {nx_, ny_, nz_};
    for (int a = 0; a < 3; ++a) {
        const Real f = std::floor((p[a] - origin_[a]) / cell_);
        if (!(f >= 0) || f >= static_cast<Real>(n[a])) return -1;  // outside (or NaN)
        idx[a] = static_cast<std::int64_t>(f);
    }
    return (idx[2] * ny_ + idx[1]) * nx_ + idx[0];
}

void BucketGrid::build(const std::vector<Vec3>& lo, const std::vector<Vec3>& hi, Real cell) {
    const std::size_t n_items = lo.size();
    nx_ = ny_ = nz_ = 0;
    start_.assign(1, 0);
    items_.clear();
    if (n_items == 0) return;
    Vec3 box_lo = lo[0], box_hi = hi[0];
    for (std::size_t i = 1; i < n_items; ++i) {
        box_lo = box_lo.cwiseMin(lo[i]);
        box_hi = box_hi.cwiseMax(hi[i]);
    }
    const Vec3 extent = (box_hi - box_lo).cwiseMax(Vec3::Constant(1e-30));
    cell_ = cell > 0 ? cell : extent.maxCoeff();
    // Cap the bucket count at ~4 per item: a crushed or exploded model keeps a bounded grid.
    const double max_buckets = 4.0 * static_cast<double>(n_items) + 64.0;
    for (;;) {
        const double b = std::ceil(extent.x() / cell_ + 1e-9) *
                         std::ceil(extent.y() / cell_ + 1e-9) *
                         std::ceil(extent.z() / cell_ + 1e-9);
        if (b <= max_buckets) break;
        cell_ *= 1.25;
    }
    origin_ = box_lo;
    nx_ =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(extent.x() / cell_ + 1e-9)));
    ny_ =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(extent.y() / cell_ + 1e-9)));
    nz_ =
        std::max<std::int64_t>(1, static_cast<std::int64_t>(std::ceil(extent.z() / cell_ + 1e-9)));
    const auto nb = static_cast<std::size_t>(nx_ * ny_ * nz_);
    start_.assign(nb + 1, 0);
    // Two passes over the items: count, then fill (counting sort into CSR).
    auto visit = [&](std::size_t i, auto&& f) {
        const std::int64_t x0 = clamp_axis(lo[i].x(), 0), x1 = clamp_axis(hi[i].x(), 0);
        const std::int64_t y0 = clamp_axis(lo[i].y(), 1), y1 = clamp_axis(hi[i].y(), 1);
        const std::int64_t z0 = clamp_axis(lo[i].z(), 2), z1 = clamp_axis(hi[i].z(), 2);
        for (std::int64_t z = z0; z <= z1; ++z)
            for (std::int64_t y = y0; y <= y1; ++y)
                for (std::int64_t x = x0; x <= x1; ++x)
                    f(static_cast<std::size_t>((z * ny_ + y) * nx_ + x));
    };
    for (std::size_t i = 0; i < n_items; ++i) visit(i, [&](std::size_t b) { ++start_[b + 1]; });
    for (std::size_t b = 0; b < nb; ++b) start_[b + 1] += start_[b];
    items_.resize(static_cast<std::size_t>(start_[nb]));
    std::vector<std::int64_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < n_items; ++i)
        visit(i, [&](std::size_t b) {
            items_[static_cast<std::size_t>(fill[b]++)] = static_cast<Index>(i);
        });
}

}  // namespace fpmshell
