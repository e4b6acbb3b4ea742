// `fcvt texture-compare INPUT OUTPUT`: how much OUTPUT's texture differs from INPUT's, seen unlit
// from the same cameras (issue 36, item 3); the yardstick is INPUT against itself moved by half a pixel.
#include "cli_common.h"
#include "commands.h"
#include "texture_files.h"

#include "errors.h"
#include "image_io.h"
#include "mesh_io.h"
#include "texture_render.h"
#include "texture_transfer.h"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <string>

namespace fieldcvt::cli {

namespace {

void printUsage()
{
    std::printf(
        "Usage: fcvt texture-compare INPUT OUTPUT [--size PX] [--views N] [--pictures PNG] [--json]\n"
        "\n"
        "Renders INPUT and OUTPUT (e.g. INPUT remeshed) with their textures, unlit, from the same N\n"
        "orthographic cameras around INPUT (every 360/N degrees about the y axis, 20 degrees\n"
        "above), PX x PX pixels each, and prints per view and on average:\n"
        "  difference  mean absolute difference of the colours (0-255, mean of R, G, B) over the pixels\n"
        "              both cover\n"
        "  half_pixel  the same between INPUT's render and INPUT's render moved by half a pixel\n"
        "              (mean of right and up): what sampling alone changes\n"
        "  ratio       difference / half_pixel (goal: at most 2)\n"
        "and seam_faces, the share of OUTPUT's faces across a seam of INPUT's atlas (their corners'\n"
        "closest points on INPUT in different charts: keeping INPUT's atlas must continue them).\n"
        "\n"
        "Options:\n"
        "  --size PX        picture size (default 512, 16-4096)\n"
        "  --views N        cameras (default 6, 1-36)\n"
        "  --pictures PNG   also write the renders: INPUT's in the top row, OUTPUT's below\n"
        "  --json           print one JSON object\n"
        "  -h, --help       show this help\n");
}

struct TexturedMesh {
    TriMesh mesh;
    MeshTexture texture;
    std::vector<TextureImage> images;
};

TexturedMesh readTextured(const std::string& path)
{
    TexturedMesh t;
    t.mesh = readMesh(path, nullptr, nullptr, &t.texture);
    if (t.texture.empty()) throw Error(path + ": no texture coordinates");
    std::vector<std::string> warnings;
    lookUpMaterialImages(t.texture, path, warnings);
    try {
        t.images = readMaterialImages(t.texture, path);
    } catch (const Error&) {
        // The look-up's reason (a FIFO, a library that is not one) says more than "no image".
        if (!warnings.empty()) throw Error(warnings.front());
        throw;
    }
    return t;
}

//! A render into column `column`, row `row` of `sheet` (white where it covers nothing).
void paste(TextureImage& sheet, const TextureRender& render, int column, int row)
{
    for (int y = 0; y < render.size; ++y)
        for (int x = 0; x < render.size; ++x) {
            const std::size_t from = static_cast<std::size_t>(y) * render.size + x;
            const Eigen::Vector3d colour =
                render.covered[from] ? Eigen::Vector3d(render.colour[from].cast<double>()) : Eigen::Vector3d::Constant(255);
            sheet.set(column * render.size + x, row * render.size + y, colour);
        }
}

}  // namespace

int runTextureCompare(const std::vector<std::string>& args)
{
    const Arguments a(args, {"size", "views", "pictures"}, {"json", "help"});
    if (printedHelp(a, printUsage)) return 0;
    const std::vector<std::string>& files = fileArguments(a, 2, "texture-compare", "INPUT and OUTPUT");
    const int size = static_cast<int>(a.integer("size", 512, 16, 4096));
    const int views = static_cast<int>(a.integer("views", 6, 1, 36));
    const TexturedMesh input = readTextured(files[0]), output = readTextured(files[1]);
    const std::vector<RenderCamera> cameras = camerasAround(input.mesh, views, size);

    TextureImage sheet;
    if (a.has("pictures")) {
        sheet.width = views * size;
        sheet.height = 2 * size;
        sheet.rgb.assign(3 * static_cast<std::size_t>(sheet.width) * sheet.height, 255);
    }
    nlohmann::ordered_json perView = nlohmann::ordered_json::array();
    double differenceSum = 0.0, halfPixelSum = 0.0;
    for (int v = 0; v < views; ++v) {
        const RenderCamera& camera = cameras[v];
        const TextureRender in = renderTextured(input.mesh, input.texture, input.images, camera);
        const TextureRender out = renderTextured(output.mesh, output.texture, output.images, camera);
        RenderCamera right = camera, up = camera;
        right.shift = {0.5, 0.0};
        up.shift = {0.0, 0.5};
        const double halfPixel =
            0.5 * (compareRenders(in, renderTextured(input.mesh, input.texture, input.images, right)).meanAbsolute +
                   compareRenders(in, renderTextured(input.mesh, input.texture, input.images, up)).meanAbsolute);
        const RenderDifference d = compareRenders(in, out);
        differenceSum += d.meanAbsolute;
        halfPixelSum += halfPixel;
        perView.push_back({{"view", v},
                           {"difference", d.meanAbsolute},
                           {"half_pixel", halfPixel},
                           {"pixels", d.pixels},
                           {"silhouette_pixels", d.onlyOne}});
        if (!sheet.empty()) {
            paste(sheet, in, v, 0);
            paste(sheet, out, v, 1);
        }
    }
    nlohmann::ordered_json j;
    j["input"] = files[0];
    j["output"] = files[1];
    j["difference"] = differenceSum / views;
    j["half_pixel"] = halfPixelSum / views;
    j["ratio"] = halfPixelSum > 0 ? differenceSum / halfPixelSum : 0.0;
    j["seam_faces"] = transferTexture(input.mesh, input.texture, output.mesh).continuedShare;
    j["views"] = perView;
    if (!sheet.empty()) writePng(*a.text("pictures"), sheet);
    if (a.flag("json")) {
        std::printf("%s\n", j.dump(2).c_str());
        return 0;
    }
    std::printf("%-6s %12s %12s %8s\n", "view", "difference", "half_pixel", "ratio");
    for (const auto& row : perView)
        std::printf(
            "%-6d %12.3f %12.3f %8.2f\n", row["view"].get<int>(), row["difference"].get<double>(),
            row["half_pixel"].get<double>(),
            row["half_pixel"].get<double>() > 0 ? row["difference"].get<double>() / row["half_pixel"].get<double>() : 0.0);
    std::printf("%-6s %12.3f %12.3f %8.2f\n", "mean", j["difference"].get<double>(), j["half_pixel"].get<double>(),
                j["ratio"].get<double>());
    std::printf("output faces across a seam of the input's atlas: %.2f %%\n", 100 * j["seam_faces"].get<double>());
    return 0;
}

}  // namespace fieldcvt::cli
