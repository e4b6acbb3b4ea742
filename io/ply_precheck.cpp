// A look at a PLY header before vcglib reads the file: vcglib allocates every element the header
// announces up front, so a corrupt or truncated file claiming billions of vertices would exhaust
// memory (or wake the OOM killer) before any read fails.
#include "io_detail.h"

#include <fstream>
#include <map>
#include <sstream>

namespace fieldcvt::io_detail {

namespace {

int scalarSize(const std::string& type)
{
    static const std::map<std::string, int> sizes = {
        {"char", 1},  {"int8", 1},   {"uchar", 1},  {"uint8", 1},   {"short", 2},   {"int16", 2},
        {"ushort", 2}, {"uint16", 2}, {"int", 4},    {"int32", 4},   {"uint", 4},    {"uint32", 4},
        {"float", 4}, {"float32", 4}, {"double", 8}, {"float64", 8}};
    const auto it = sizes.find(type);
    return it == sizes.end() ? 0 : it->second;
}

}  // namespace

void checkPlySize(const std::string& path, std::uintmax_t fileSize)
{
    std::ifstream in(path, std::ios::binary);
    std::string line;
    bool ascii = false;
    std::uintmax_t headerBytes = 0;
    // Smallest possible size of the body: per element, its count times the bytes of its fixed
    // properties (binary) or one digit and one separator per property (ASCII).
    long double minimumBody = 0;
    long double count = 0;
    std::string elements;
    while (std::getline(in, line)) {
        headerBytes += line.size() + 1;
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        if (keyword == "format") {
            std::string format;
            words >> format;
            ascii = format == "ascii";
        } else if (keyword == "element") {
            std::string name;
            long double n = -1;
            words >> name >> n;
            if (!words || n < 0) return;  // malformed header: vcglib reports it
            count = n;
            elements += (elements.empty() ? "" : ", ") + std::to_string(static_cast<long long>(n)) + " '" + name + "'";
        } else if (keyword == "property") {
            std::string type;
            words >> type;
            const int bytes = type == "list" ? [&] { std::string countType; words >> countType; return scalarSize(countType); }()
                                             : scalarSize(type);
            minimumBody += count * (ascii ? 2 : bytes);
        } else if (keyword == "end_header") {
            if (headerBytes + minimumBody > static_cast<long double>(fileSize))
                fail(path, "truncated PLY file: its header announces " + elements + " elements but the file has only " +
                               std::to_string(fileSize) + " bytes");
            return;
        }
    }
}

}  // namespace fieldcvt::io_detail
