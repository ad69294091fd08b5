// Broad phase of contact (theory.md §8.1): a uniform grid of buckets over the bounding box
// of the items, each item registered in every bucket its box overlaps, stored as one CSR
// array (no per-bucket allocation). Building and querying cost O(items) for boxes no larger
// than a bucket, so the contact search grows linearly with the mesh.
#pragma once

#include <cstdint>
#include <vector>

#include "fpmshell/core/types.hpp"

namespace fpmshell {

class BucketGrid {
public:
    /// Registers item i with the box [lo[i], hi[i]]. The bucket edge is at least `cell`, and
    /// larger when the box would need more than about 8 buckets per item.
    void build(const std::vector<Vec3>& lo, const std::vector<Vec3>& hi, Real cell);

    /// Calls f(item) for every item registered in the bucket that contains p (an item whose
    /// box contains p is always among them; others may be too).
    template <class F>
    void for_each_near(const Vec3& p, F&& f) const {
        const std::int64_t b = bucket_of(p);
        if (b < 0) return;
        for (std::int64_t k = start_[static_cast<std::size_t>(b)];
             k < start_[static_cast<std::size_t>(b) + 1]; ++k)
            f(items_[static_cast<std::size_t>(k)]);
    }

    [[nodiscard]] Real cell() const { return cell_; }
    [[nodiscard]] std::int64_t buckets() const { return nx_ * ny_ * nz_; }

private:
    [[nodiscard]] std::int64_t bucket_of(const Vec3& p) const;
    [[nodiscard]] std::int64_t clamp_axis(Real coordinate, int axis) const;

    Vec3 origin_ = Vec3::Zero();
    Real cell_ = 1;
    std::int64_t nx_ = 0, ny_ = 0, nz_ = 0;
    std::vector<std::int64_t> start_;  ///< CSR offsets, buckets() + 1
    std::vector<Index> items_;
};

}  // namespace fpmshell
