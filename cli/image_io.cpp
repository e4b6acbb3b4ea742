// stb's implementations are compiled here, once, private to this file.
#include "image_io.h"

#include "errors.h"

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
    int width = 0, height = 0, channels = 0;
    unsigned char* pixels = stbi_load(path.c_str(), &width, &height, &channels, 3);
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
    if (!stbi_write_png(path.c_str(), image.width, image.height, 3, image.rgb.data(), 3 * image.width))
        throw Error(path + ": cannot write the PNG");
}

}  // namespace fieldcvt
