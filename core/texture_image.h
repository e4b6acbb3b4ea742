#pragma once
// A decoded texture image in memory: what the renderer samples and the baker reads
// and fills. Reading and writing image files is the front ends' job (io/image_io.h, QImage).
#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace fieldcvt {

//! 8-bit RGB pixels, row 0 at the top of the picture (as PNG and JPEG store them). Texture
//! coordinates follow OBJ's convention: (0, 0) is the bottom-left corner, (1, 1) the top-right,
//! and the picture repeats outside [0, 1] (OpenGL's GL_REPEAT, MeshLab's default).
struct TextureImage {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;  //!< 3 per pixel, row by row

    bool empty() const { return width <= 0 || height <= 0; }

    Eigen::Vector3d pixel(int x, int y) const
    {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
        return {double(rgb[i]), double(rgb[i + 1]), double(rgb[i + 2])};
    }

    //! Sets pixel (x, y) to `colour` (0 .. 255 per channel), rounded and clamped to that range.
    void set(int x, int y, const Eigen::Vector3d& colour)
    {
        const std::size_t i = 3 * (static_cast<std::size_t>(y) * width + x);
        for (int k = 0; k < 3; ++k) rgb[i + k] = static_cast<std::uint8_t>(std::lround(std::clamp(colour[k], 0.0, 255.0)));
    }

    //! The colour at (u, v), bilinear between the four nearest pixel centres (0 .. 255 each).
    Eigen::Vector3d sample(double u, double v) const
    {
        if (!std::isfinite(u) || !std::isfinite(v)) return Eigen::Vector3d::Zero();
        const double x = u * width - 0.5, y = (1.0 - v) * height - 0.5;
        const double fx = std::floor(x), fy = std::floor(y);
        const double tx = x - fx, ty = y - fy;
        // Reduced into one period first: coordinates continued far outside [0, 1] stay in range.
        const int x0 = wrap(std::fmod(fx, width), width), x1 = wrap(std::fmod(fx, width) + 1, width);
        const int y0 = wrap(std::fmod(fy, height), height), y1 = wrap(std::fmod(fy, height) + 1, height);
        return (1 - ty) * ((1 - tx) * pixel(x0, y0) + tx * pixel(x1, y0)) + ty * ((1 - tx) * pixel(x0, y1) + tx * pixel(x1, y1));
    }

private:
    //! An integer-valued i with |i| <= n, wrapped into [0, n).
    static int wrap(double i, int n)
    {
        const long long k = static_cast<long long>(i) % n;
        return static_cast<int>(k < 0 ? k + n : k);
    }
};

}  // namespace fieldcvt
