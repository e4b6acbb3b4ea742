// stb's implementations are compiled here, once, private to this file.
#include "image_io.h"

#include "errors.h"
#include "side_files.h"

#include <cstdint>
#include <cstdlib>
#include <filesystem>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_FAILURE_USERMSG
#include <stb/stb_image.h>
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>

namespace fieldcvt {

TextureImage readImage(const std::string& path)
{
    // Read as any side file (a regular file, bounded), then decoded only when its size is bounded too.
    const SideFileLimits& limits = sideFileLimits();
    const std::string bytes = readSideFile(path, limits.imageBytes);
    const auto* data = reinterpret_cast<const stbi_uc*>(bytes.data());
    const int length = static_cast<int>(bytes.size());
    int width = 0, height = 0, channels = 0;
    if (!stbi_info_from_memory(data, length, &width, &height, &channels))
        throw Error(path + ": cannot read the image (" + stbi_failure_reason() + ")");
    if (width > limits.imageSide || height > limits.imageSide ||
        std::uint64_t(width) * std::uint64_t(height) > limits.imagePixels)
        throw Error(path + ": the image is " + std::to_string(width) + " x " + std::to_string(height) +
                    " pixels, over the limit of " + std::to_string(limits.imagePixels / 1000000) + " Mpixel and " +
                    std::to_string(limits.imageSide) + " a side");
    unsigned char* pixels = stbi_load_from_memory(data, length, &width, &height, &channels, 3);
    if (!pixels) throw Error(path + ": cannot read the image (" + stbi_failure_reason() + ")");
    TextureImage image;
    image.width = width;
    image.height = height;
    image.rgb.assign(pixels, pixels + 3 * static_cast<std::size_t>(width) * height);
    stbi_image_free(pixels);
    return image;
}

std::vector<TextureImage> readMaterialImages(const MeshTexture& texture, const std::string& meshPath)
{
    const std::filesystem::path folder = std::filesystem::path(meshPath).parent_path();
    std::vector<TextureImage> images;
    for (const TextureMaterial& m : texture.materials) {
        if (m.image.empty()) throw Error(meshPath + ": material '" + m.name + "' names no texture image");
        images.push_back(readImage((folder / m.image).string()));
    }
    return images;
}

void writePng(const std::string& path, const TextureImage& image)
{
    if (image.empty() || image.rgb.size() != 3 * static_cast<std::size_t>(image.width) * image.height)
        throw Error(path + ": no image to write");
    int length = 0;
    unsigned char* png = stbi_write_png_to_mem(image.rgb.data(), 3 * image.width, image.width, image.height, 3, &length);
    if (!png) throw Error(path + ": cannot encode the PNG");
    const std::string bytes(reinterpret_cast<const char*>(png), static_cast<std::size_t>(length));
    STBIW_FREE(png);
    writeFileReplacing(path, bytes);  // never through a link, never half a file
}

}  // namespace fieldcvt
