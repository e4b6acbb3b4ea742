#include "morton_order.h"

#include <algorithm>
#include <cstdint>
#include <limits>
#include <utility>

namespace fieldcvt {

std::vector<int> mortonIndexOrder(const std::vector<Vec3>& points)
{
    Vec3 lo = Vec3::Constant(std::numeric_limits<double>::max()), hi = -lo;
    for (const Vec3& p : points) lo = lo.cwiseMin(p), hi = hi.cwiseMax(p);
    const Vec3 extent = (hi - lo).cwiseMax(Vec3::Constant(1e-300));
    auto spread = [](uint64_t x) {  // 21 bits -> every third bit of 63
        x &= 0x1fffff;
        x = (x | x << 32) & 0x1f00000000ffffULL;
        x = (x | x << 16) & 0x1f0000ff0000ffULL;
        x = (x | x << 8) & 0x100f00f00f00f00fULL;
        x = (x | x << 4) & 0x10c30c30c30c30c3ULL;
        x = (x | x << 2) & 0x1249249249249249ULL;
        return x;
    };
    std::vector<std::pair<uint64_t, int>> keys(points.size());
    for (size_t i = 0; i < points.size(); ++i) {
        const Vec3 q = ((points[i] - lo).array() / extent.array() * 2097151.0).matrix();
        keys[i] = {spread(static_cast<uint64_t>(q.x())) | spread(static_cast<uint64_t>(q.y())) << 1 |
                       spread(static_cast<uint64_t>(q.z())) << 2,
                   static_cast<int>(i)};
    }
    std::sort(keys.begin(), keys.end());
    std::vector<int> order(points.size());
    for (size_t i = 0; i < keys.size(); ++i) order[i] = keys[i].second;
    return order;
}

}  // namespace fieldcvt
