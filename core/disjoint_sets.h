#pragma once
// Union-find with path halving (no recursion: deep chains on large meshes are fine); the smaller
// index becomes the root, so roots are deterministic (the first element of each set).
#include <algorithm>
#include <numeric>
#include <vector>

namespace fieldcvt {

struct DisjointSets {
    std::vector<int> parent;
    explicit DisjointSets(int n = 0) : parent(n) { std::iota(parent.begin(), parent.end(), 0); }
    int find(int x)
    {
        while (parent[x] != x) x = parent[x] = parent[parent[x]];
        return x;
    }
    void unite(int a, int b)
    {
        a = find(a), b = find(b);
        if (a != b) parent[std::max(a, b)] = std::min(a, b);
    }
};

}  // namespace fieldcvt
