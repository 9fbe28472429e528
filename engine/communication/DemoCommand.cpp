// `mixengine demo [dir]`: a self-contained first run — writes a 20 mm cube as binary STL, slices
// it with the installed Cura defaults and a colour gradient (filament A up to 20 % of the height,
// B from 80 %, E and B axis words) and says where the G-code and its preview went.
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <ostream>

#include "communication/Commands.h"
#include "communication/OutputFile.h"

namespace mixengine {
namespace {

void putFloat(std::string& out, float value) {
    char bytes[4];
    std::memcpy(bytes, &value, 4);
    out.append(bytes, 4);
}

/// A binary STL of an axis-aligned cube with edge `size_mm`, centred in XY, bottom at z=0.
std::string cubeStl(float size_mm) {
    const float h = size_mm / 2;
    const float v[8][3] = {{-h, -h, 0},       {h, -h, 0},       {h, h, 0},       {-h, h, 0},
                           {-h, -h, size_mm}, {h, -h, size_mm}, {h, h, size_mm}, {-h, h, size_mm}};
    const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                              {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    std::string out(80, ' ');
    out.replace(0, 22, "MixEngine demo cube 20");
    const std::uint32_t count = 12;
    out.append(reinterpret_cast<const char*>(&count), 4);
    for (const auto& face : faces) {
        for (int k = 0; k < 3; ++k)
            putFloat(out, 0.0f);
        for (int corner : face)
            for (int k = 0; k < 3; ++k)
                putFloat(out, v[corner][k]);
        out.append(2, '\0');
    }
    return out;
}

}  // namespace

int runDemoCommand(const Words& args, std::ostream& out, std::ostream& err) {
    const std::filesystem::path dir = args.empty() ? "out" : args.front();
    std::filesystem::create_directories(dir);
    const std::filesystem::path model = dir / "cube20.stl";
    const std::filesystem::path gcode = dir / "demo.gcode";
    const std::filesystem::path preview = dir / "demo.png";
    writeFileAtomically(model, cubeStl(20.0f));
    const int code = runSliceCommand(
        {"-s", "mixing_mode=gradient", "-s", "mixing_gradient_start=20", "-s", "mixing_gradient_end=80", "-l",
         model.string(), "-o", gcode.string(), "--preview", preview.string()},
        out, err);
    if (code == 0) {
        out << "G-code written to " << std::filesystem::absolute(gcode).string() << '\n';
        out << "Gradient preview written to " << std::filesystem::absolute(preview).string() << '\n';
    }
    return code;
}

}  // namespace mixengine
