// Atomic writing of result files (communication/OutputFile.h).
#include "communication/OutputFile.h"

#include <gtest/gtest.h>

#include "common/TextFile.h"
#include "unit/settings/ScratchDir.h"

namespace mixengine {
namespace {

namespace fs = std::filesystem;
using unit::contains;
using unit::inputErrorOf;
using unit::ScratchDir;

TEST(OutputFile, WritesTheWholeTextAndNoTemporaryRemains) {
    ScratchDir dir;
    const fs::path target = dir.path() / "out.gcode";
    const std::string text = ";FLAVOR:Marlin\nG1 X1 Y2 E0.5\n" + std::string(100'000, 'x') + "\n";
    writeFileAtomically(target, text);
    EXPECT_EQ(readTextFile(target), text);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.gcode"}));
}

TEST(OutputFile, ReplacesAnExistingFile) {
    ScratchDir dir;
    const fs::path target = dir.write("out.gcode", "old content that is longer than the new one\n");
    writeFileAtomically(target, "new\n");
    EXPECT_EQ(readTextFile(target), "new\n");
    writeFileAtomically(target, "");
    EXPECT_TRUE(fs::exists(target));
    EXPECT_EQ(fs::file_size(target), 0U);
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.gcode"}));
}

TEST(OutputFile, MissingDirectoryIsAnInputErrorNamingThePath) {
    ScratchDir dir;
    const fs::path target = dir.path() / "no_such_dir" / "out.gcode";
    const std::string message = inputErrorOf([&] { writeFileAtomically(target, "G28\n"); });
    EXPECT_TRUE(contains(message, target.string())) << message;
    EXPECT_FALSE(fs::exists(dir.path() / "no_such_dir"));
    EXPECT_TRUE(dir.entries().empty());
}

TEST(OutputFile, TargetIsADirectoryLeavesNothingBehind) {
    ScratchDir dir;
    fs::create_directory(dir.path() / "out.gcode");
    const fs::path target = dir.path() / "out.gcode";
    const std::string message = inputErrorOf([&] { writeFileAtomically(target, "G28\n"); });
    EXPECT_TRUE(contains(message, target.string())) << message;
    EXPECT_EQ(dir.entries(), (std::vector<std::string>{"out.gcode"}));
    EXPECT_TRUE(fs::is_directory(target));
}

}  // namespace
}  // namespace mixengine
