#include "layer_texture.h"

#include "mesh_convert.h"

#include "errors.h"
#include "side_files.h"
#include "texture_output.h"

#include <QBuffer>
#include <QFileInfo>
#include <QImage>
#include <QImageReader>

#include <algorithm>
#include <cmath>

namespace fcvt_plugin {

fieldcvt::MeshTexture layerTexture(const MeshModel& layer, const fieldcvt::TriMesh& layerMesh, QString* problem)
{
    fieldcvt::MeshTexture texture;
    if (!layer.hasDataMask(MeshModel::MM_WEDGTEXCOORD)) return texture;
    for (const std::string& name : layer.cm.textures) texture.materials.push_back({name, name});
    if (texture.materials.empty()) texture.materials.push_back({"", ""});  // coordinates without an image
    texture.uv.reserve(3 * layerMesh.faces.size());
    for (const CFaceO& f : layer.cm.face) {
        if (f.IsD()) continue;
        for (int k = 0; k < 3; ++k) texture.uv.emplace_back(double(f.cWT(k).U()), double(f.cWT(k).V()));
        const int index = f.cWT(0).N();
        texture.faceMaterial.push_back(index >= 0 && index < int(texture.materials.size()) ? index : -1);
    }
    const std::string why = fieldcvt::textureProblem(layerMesh, texture);
    if (!why.empty()) {
        if (problem) *problem = QString::fromStdString(why);
        return {};
    }
    return texture;
}

namespace {

fieldcvt::TextureImage toTextureImage(const QImage& image)
{
    const QImage rgb = image.convertToFormat(QImage::Format_RGB888);
    fieldcvt::TextureImage t;
    t.width = rgb.width();
    t.height = rgb.height();
    t.rgb.resize(3 * size_t(t.width) * size_t(t.height));
    for (int y = 0; y < t.height; ++y)
        std::copy(rgb.constScanLine(y), rgb.constScanLine(y) + 3 * t.width, t.rgb.begin() + 3 * size_t(y) * t.width);
    return t;
}

QImage toQImage(const fieldcvt::TextureImage& t)
{
    QImage image(t.width, t.height, QImage::Format_RGB888);
    for (int y = 0; y < t.height; ++y)
        std::copy(t.rgb.begin() + 3 * size_t(y) * t.width, t.rgb.begin() + 3 * size_t(y + 1) * t.width, image.scanLine(y));
    return image;
}

//! The input layer's images, one per texture; empty, with the reason in `problem`, when one cannot
//! be had. MeshLab 2022.02 and later hold them in the layer (a texture it could not load is named
//! "dummy.png" and shows a placeholder); 2020.09 holds only names, read here as MeshLab does:
//! relative to the layer's file, and as the CLI reads them: a regular file, bounded in bytes and
//! pixels (io/side_files.h), so that a FIFO or a device named as a texture cannot hang MeshLab.
std::vector<fieldcvt::TextureImage> layerImages(const MeshModel& input, QString& problem)
{
    std::vector<fieldcvt::TextureImage> images;
    for (const std::string& name : input.cm.textures) {
#if FCVT_MESHLAB_API == 2022
        const QImage image = input.getTexture(name);
        if (name == "dummy.png") {
            problem = "the input's texture images could not be loaded by MeshLab";
            return {};
        }
#else
        const QString file = QString::fromStdString(name);
        const QString path = QFileInfo(file).isAbsolute() ? file : input.pathName() + "/" + file;
        const fieldcvt::SideFileLimits& limits = fieldcvt::sideFileLimits();
        QByteArray bytes;
        try {
            const std::string read = fieldcvt::readSideFile(path.toStdString(), limits.imageBytes);
            bytes = QByteArray(read.data(), int(read.size()));
        } catch (const fieldcvt::Error& e) {
            problem = QString("texture image ") + e.what();
            return {};
        }
        QBuffer buffer(&bytes);
        QImageReader reader(&buffer);
        const QSize size = reader.size();
        if (size.width() > limits.imageSide || size.height() > limits.imageSide ||
            quint64(std::max(size.width(), 0)) * quint64(std::max(size.height(), 0)) > limits.imagePixels) {
            problem = QString("texture image %1 is %2 x %3 pixels, over the limit of %4 Mpixel")
                          .arg(path)
                          .arg(size.width())
                          .arg(size.height())
                          .arg(limits.imagePixels / 1000000);
            return {};
        }
        const QImage image = reader.read();
#endif
        if (image.isNull()) {
            problem = "the input's texture image " + QString::fromStdString(name) + " cannot be read";
            return {};
        }
        images.push_back(toTextureImage(image));
    }
    return images;
}

//! Gives `output` its textures: the input's first when kept faces still use them (`inputKept`),
//! then the baked image under `name`: in the layer (2022.02 and later; File > Export Mesh saves it
//! beside the mesh) or, in 2020.09, whose layers hold only names, as a PNG beside the input's
//! file (as MeshLab's own texture filters write theirs), never over an existing file: `name`
//! then gets a number ("bunny_FCVT_texture_2.png"). An error text, or empty.
QString storeBakedImage(const MeshModel& input, bool inputKept, const QImage& image, std::string& name, MeshModel& output)
{
#if FCVT_MESHLAB_API == 2022
    output.clearTextures();
    if (inputKept)
        for (const std::string& texture : input.cm.textures) output.addTexture(texture, input.getTexture(texture));
    output.addTexture(name, image);
    return {};
#else
    if (input.fullName().isEmpty()) return "the input layer has no file to write the image beside";
    QByteArray png;
    QBuffer buffer(&png);
    if (!buffer.open(QIODevice::WriteOnly) || !image.save(&buffer, "PNG")) return "cannot encode the baked image as PNG";
    // The names the CLI gives its side files (side_files.h): any entry there counts, a dangling
    // link too, so the image is written through no link and over no file.
    QString file;
    try {
        fieldcvt::SideFileNames names(false);
        std::vector<std::string> renamed;
        const std::string path = names.choose((input.pathName() + "/" + QString::fromStdString(name)).toStdString(), renamed);
        fieldcvt::writeFileReplacing(path, std::string(png.constData(), size_t(png.size())));
        file = QFileInfo(QString::fromStdString(path)).fileName();
    } catch (const fieldcvt::Error& e) {
        return QString("cannot write the baked image: ") + e.what();
    }
    name = file.toStdString();
    output.cm.textures = inputKept ? input.cm.textures : std::vector<std::string>{};
    output.cm.textures.push_back(name);
    return {};
#endif
}

void writeWedges(const fieldcvt::MeshTexture& texture, MeshModel& output)
{
    output.updateDataMask(MeshModel::MM_WEDGTEXCOORD);
    size_t f = 0;
    for (CFaceO& face : output.cm.face) {
        if (face.IsD()) continue;
        for (int k = 0; k < 3; ++k) {
            const fieldcvt::Vec2& uv = texture.uv[3 * f + k];
            face.WT(k).U() = Scalarm(uv.x());
            face.WT(k).V() = Scalarm(uv.y());
            face.WT(k).N() = short(texture.faceMaterial[f]);
        }
        ++f;
    }
}

}  // namespace

QString transferLayerTexture(const MeshModel& input, const fieldcvt::TriMesh& outputMesh, const std::vector<int>& faceOrigin,
                             int threads, MeshModel& output)
{
    const fieldcvt::TriMesh layerMesh = toTriMesh(input.cm);
    QString problem;
    const fieldcvt::MeshTexture texture = layerTexture(input, layerMesh, &problem);
    if (texture.empty())
        return problem.isEmpty() ? QString() : "FCVT: texture coordinates of '" + input.label() + "' dropped: " + problem;
    if (size_t(output.cm.fn) != outputMesh.faces.size()) return "FCVT: texture coordinates not carried (face count changed)";
    fieldcvt::OutputTextureParams params;
    params.threads = threads;
    QString imageProblem;
    const std::vector<fieldcvt::TextureImage> images = layerImages(input, imageProblem);
    fieldcvt::OutputTexture made = fieldcvt::makeOutputTexture(layerMesh, texture, images, outputMesh, faceOrigin, params);
    const QString seams = QString("%1 charts, %2 new faces (%3 %) across a seam")
                              .arg(made.charts)
                              .arg(made.continuedFaces)
                              .arg(100.0 * made.continuedShare, 0, 'f', 2);
    QString bakeProblem =
        made.tooManyFacesToBake ? QString("too many faces for a texture of %1 x %1 texels").arg(params.bakeMaxSize)
        : made.bakeImpossible   ? (imageProblem.isEmpty() ? "the input's texture images cannot be read" : imageProblem)
                                : QString();
    if (made.baked) {
        std::string name = output.label().toStdString() + "_texture.png";
        bakeProblem = storeBakedImage(input, made.bakedMaterial > 0, toQImage(made.bakedImage), name, output);
        if (bakeProblem.isEmpty()) {
            writeWedges(made.texture, output);
            return QString(
                       "FCVT: texture baked into '%1' (%2 x %3, one triangle per face): keeping the input's atlas (%4) "
                       "would stretch them")
                .arg(QString::fromStdString(name))
                .arg(made.bakedImage.width)
                .arg(made.bakedImage.height)
                .arg(seams);
        }
        // The image could not be stored: the atlas kept after all.
        params.method = fieldcvt::TextureMethod::Keep;
        made = fieldcvt::makeOutputTexture(layerMesh, texture, {}, outputMesh, faceOrigin, params);
    }
    writeWedges(made.texture, output);
#if FCVT_MESHLAB_API == 2022
    output.clearTextures();
    for (const std::string& name : input.cm.textures) output.addTexture(name, input.getTexture(name));
#else
    output.cm.textures = input.cm.textures;  // MeshLab 2020.09 loads the images by name when it draws
#endif
    if (!bakeProblem.isEmpty())
        return "FCVT: texture kept in the input's atlas (" + seams + ", continued there): no texture baked: " + bakeProblem;
    return "FCVT: texture kept in the input's atlas: " + seams + ", continued there";
}

}  // namespace fcvt_plugin
