#pragma once
// A hash for keys of three numbers (coordinates, grid cells, a face's sorted corners) in the
// unordered containers of the repair and the input check: their bits mixed as boost's
// hash_combine does.
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace fieldcvt {

struct TripleHash {
    template <class T>
    std::size_t operator()(const std::array<T, 3>& key) const
    {
        static_assert(sizeof(T) <= sizeof(std::uint64_t), "keys of at most 8 bytes");
        std::uint64_t h = 0;
        for (const T& x : key) {
            std::uint64_t bits = 0;
            std::memcpy(&bits, &x, sizeof(T));
            h ^= bits + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
        }
        return std::size_t(h);
    }
};

}  // namespace fieldcvt
