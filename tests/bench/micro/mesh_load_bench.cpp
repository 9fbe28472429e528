// Mesh input speed: reading an 832,050-triangle binary STL (a wavy grid, like a 41 MB scan) and
// building the indexed mesh. Prints wall and CPU time; no threshold. Its correctness is tested in
// tests/unit/mesh/mesh_large_stl_test.cpp.
#include "bench/micro/Stopwatch.h"
#include "mesh/build/MeshBuilder.h"
#include "mesh/formats/ModelReader.h"
#include "unit/mesh/MeshTestFiles.h"

int main() {
    using namespace mixengine;
    test::TempDir dir;
    const auto file = dir.write("grid.stl", test::binaryStl(test::wavyGridTriangles()));
    std::size_t face_count = 0;
    const bench::Timing t = bench::timed([&] {
        std::vector<std::string> warnings;
        const auto parts = readModelFile(file, warnings);
        face_count = buildMesh(parts.at(0), Matrix3{}).faces.size();
    });
    const std::string what = std::to_string(face_count) + "-triangle binary STL, load + build";
    bench::printTiming("mesh_load", t, what.c_str());
    return 0;
}
