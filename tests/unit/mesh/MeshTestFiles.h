#pragma once
// Helpers for the mesh input tests: a temporary directory removed at the end of the test, and
// generators of model files (binary / ASCII STL bytes of given triangles, a unit cube soup, a
// large wavy grid).
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>
#include <stdlib.h>

#include "common/Error.h"
#include "mesh/formats/ModelReader.h"

namespace mixengine::test {

using Triangle = std::array<Vec3, 3>;

class TempDir {
  public:
    TempDir() {
        std::string pattern = (std::filesystem::temp_directory_path() / "mixengine-mesh-XXXXXX").string();
        if (mkdtemp(pattern.data()) != nullptr) {
            path_ = pattern;
        }
    }
    ~TempDir() {
        std::error_code ignored;
        std::filesystem::remove_all(path_, ignored);
    }
    TempDir(const TempDir&) = delete;
    TempDir& operator=(const TempDir&) = delete;

    /// Writes `bytes` to a file named `name` in the directory and returns its path.
    std::filesystem::path write(const std::string& name, std::string_view bytes) const {
        const std::filesystem::path file = path_ / name;
        std::ofstream out(file, std::ios::binary);
        out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        return file;
    }
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

/// A wavy `quads` x `quads` grid of quads: 2·quads² triangles sharing (quads + 1)² vertices; the
/// default is 832,050 triangles, like a 41 MB scan.
inline std::vector<Triangle> wavyGridTriangles(int quads = 645) {
    auto at = [](int i, int j) {
        return Vec3{i * 0.31, j * 0.29, 5.0 + std::sin(i * 0.05) * std::cos(j * 0.07)};
    };
    std::vector<Triangle> triangles;
    triangles.reserve(2 * static_cast<std::size_t>(quads) * static_cast<std::size_t>(quads));
    for (int i = 0; i < quads; ++i) {
        for (int j = 0; j < quads; ++j) {
            triangles.push_back({at(i, j), at(i + 1, j), at(i + 1, j + 1)});
            triangles.push_back({at(i, j), at(i + 1, j + 1), at(i, j + 1)});
        }
    }
    return triangles;
}

/// The 12 triangles of the cube [0, size]^3, outward winding.
inline std::vector<Triangle> cubeTriangles(double size = 10.0) {
    const double s = size;
    const Vec3 p[8] = {{0, 0, 0}, {s, 0, 0}, {s, s, 0}, {0, s, 0},
                       {0, 0, s}, {s, 0, s}, {s, s, s}, {0, s, s}};
    const int faces[12][3] = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                              {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    std::vector<Triangle> triangles;
    for (const auto& f : faces) {
        triangles.push_back({p[f[0]], p[f[1]], p[f[2]]});
    }
    return triangles;
}

inline void appendFloat(std::string& bytes, float value) {
    char raw[4];
    std::memcpy(raw, &value, 4);
    bytes.append(raw, 4);
}

/// Binary STL of `triangles` whose header counter is `counter` and whose 80-byte header starts
/// with `header_text`. Normals are (0, 0, normal_z).
inline std::string binaryStl(const std::vector<Triangle>& triangles, std::uint32_t counter,
                             std::string_view header_text = "binary", float normal_z = 1.0F) {
    std::string bytes(header_text.substr(0, 80));
    bytes.resize(80, ' ');
    char raw[4];
    std::memcpy(raw, &counter, 4);
    bytes.append(raw, 4);
    for (const Triangle& t : triangles) {
        appendFloat(bytes, 0.0F);
        appendFloat(bytes, 0.0F);
        appendFloat(bytes, normal_z);
        for (const Vec3& v : t) {
            appendFloat(bytes, static_cast<float>(v.x));
            appendFloat(bytes, static_cast<float>(v.y));
            appendFloat(bytes, static_cast<float>(v.z));
        }
        bytes.append(2, '\0');
    }
    return bytes;
}

inline std::string binaryStl(const std::vector<Triangle>& triangles) {
    return binaryStl(triangles, static_cast<std::uint32_t>(triangles.size()));
}

/// One ASCII STL `solid` block holding `triangles`.
inline std::string asciiSolid(const std::vector<Triangle>& triangles, const std::string& name = "cube") {
    std::string text = "solid " + name + "\n";
    for (const Triangle& t : triangles) {
        text += "  facet normal 0 0 1\n    outer loop\n";
        for (const Vec3& v : t) {
            text += "      vertex " + std::to_string(v.x) + " " + std::to_string(v.y) + " " +
                    std::to_string(v.z) + "\n";
        }
        text += "    endloop\n  endfacet\n";
    }
    return text + "endsolid " + name + "\n";
}

/// EXPECT_TRUE(contains(message, "part")) prints both strings when it fails.
inline ::testing::AssertionResult contains(const std::string& text, const std::string& part) {
    if (text.find(part) != std::string::npos) {
        return ::testing::AssertionSuccess();
    }
    return ::testing::AssertionFailure() << "'" << text << "' does not contain '" << part << "'";
}

/// The message of the InputError thrown by `action` (a test failure when none is thrown). Also
/// checks the message is a single line.
template <typename Action>
std::string inputErrorOf(Action&& action) {
    try {
        action();
    } catch (const InputError& error) {
        const std::string message = error.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        return message;
    }
    ADD_FAILURE() << "expected an InputError";
    return {};
}

}  // namespace mixengine::test
