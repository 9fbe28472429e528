#pragma once
// The stages of a slice that report progress (Log::progress), in pipeline order. One value for
// every reporter and every listener: the command line prints the stage's name (-p), Cura's socket
// (communication/arcus) maps the stage onto Cura's progress bar.
namespace mixengine {

enum class ProgressStage {
    Slicing,    ///< cutting the meshes into layers (fraction: of the layers cut)
    Toolpaths,  ///< toolpaths, planning and mixing of a mesh group
    GCode,      ///< writing the G-code of a mesh group
    Done,       ///< the whole print is written
};

/// The word -p prints: "slicing", "toolpaths", "gcode", "done".
constexpr const char* progressStageName(ProgressStage stage) {
    switch (stage) {
        case ProgressStage::Slicing:
            return "slicing";
        case ProgressStage::Toolpaths:
            return "toolpaths";
        case ProgressStage::GCode:
            return "gcode";
        case ProgressStage::Done:
            return "done";
    }
    return "";
}

}  // namespace mixengine
