"""Tests of include_cycles.py on small trees made in a temporary folder: it passes an acyclic tree,
and on a cycle it exits 1 naming the folders and printing the include lines to move."""
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

SCRIPT = Path(__file__).with_name("include_cycles.py")


def run(files, *options):
    """(exit code, stdout) of the script (with `options`) on a tree of {relative path: text}."""
    with tempfile.TemporaryDirectory() as tmp:
        root = Path(tmp)
        for name, text in files.items():
            path = root / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_text(text)
        proc = subprocess.run([sys.executable, str(SCRIPT), *options, str(root)], capture_output=True, text=True)
        return proc.returncode, proc.stdout


class IncludeCycles(unittest.TestCase):
    def test_layered_tree_passes(self):
        rc, out = run({
            "common/Log.h": "#pragma once\n",
            "slicing/Slicer.h": '#include "common/Log.h"\n',
            "pipeline/Driver.cpp": '#include "slicing/Slicer.h"\n#include "common/Log.h"\n',
            "main.cpp": '#include "pipeline/Driver.h"\n',
        })
        self.assertEqual(rc, 0, out)
        self.assertIn("no include cycle between the 4 stage folders", out)

    def test_cycle_fails_and_prints_the_upward_include(self):
        rc, out = run({
            "low/A.h": '#include "high/Scene.h"\n',
            "high/Scene.h": '#include "low/A.h"\n',
            "high/Scene.cpp": '#include "high/Scene.h"\n#include "low/A.h"\n',
        })
        self.assertEqual(rc, 1, out)
        self.assertIn("include cycle between 2 folders: high, low", out)
        self.assertIn("(lowest first): low < high", out)
        self.assertIn('low -> high: low/A.h:1: #include "high/Scene.h"', out)
        self.assertNotIn("high -> low", out)

    def test_three_folder_cycle_names_one_line(self):
        rc, out = run({
            "a/A.h": '#include "b/B.h"\n',
            "a/A.cpp": '#include "b/B.h"\n',
            "b/B.h": '#include "c/C.h"\n',
            "b/B.cpp": '#include "c/C.h"\n',
            "c/C.h": '#include <vector>\n\n#include "a/A.h"\n',
            "d/D.h": '#include "a/A.h"\n',
        })
        self.assertEqual(rc, 1, out)
        self.assertIn("include cycle between 3 folders: a, b, c", out)
        self.assertIn("the 1 include line(s)", out)
        self.assertIn('c -> a: c/C.h:3: #include "a/A.h"', out)

    def test_subfolder_belongs_to_its_stage(self):
        rc, out = run({
            "settings/profiles/Selector.h": '#include "request/Request.h"\n#include "settings/Settings.h"\n',
            "settings/Settings.h": "#pragma once\n",
            "request/Request.h": '#include "settings/Settings.h"\n',
            "request/Request.cpp": '#include "settings/Settings.h"\n',
        })
        self.assertEqual(rc, 1, out)
        self.assertIn("settings -> request: settings/profiles/Selector.h:1:", out)

    def test_other_libraries_comments_and_own_stage_are_no_edges(self):
        rc, out = run({
            "a/A.h": '#include <nlohmann/json.hpp>\n// #include "b/B.h"\n#include "a/Other.h"\n',
            "a/Other.h": '#include "Local.pb.h"\n',
            "b/B.h": '#include "a/A.h"\n',
        })
        self.assertEqual(rc, 0, out)

    def test_rooms_of_a_stage_without_cycle_pass(self):
        rc, out = run({
            "toolpaths/core/Path.h": "#pragma once\n",
            "toolpaths/walls/Walls.h": '#include "toolpaths/core/Path.h"\n',
            "toolpaths/Group.cpp": '#include "toolpaths/walls/Walls.h"\n#include "common/Log.h"\n',
            "common/Log.h": "#pragma once\n",
        }, "--rooms")
        self.assertEqual(rc, 0, out)
        self.assertIn("no include cycle between the 3 rooms", out)

    def test_cycle_between_rooms_fails_and_prints_the_upward_include(self):
        rc, out = run({
            "toolpaths/Group.h": '#include "toolpaths/walls/Walls.h"\n',
            "toolpaths/walls/Walls.h": '#include "toolpaths/Group.h"\n',
            "toolpaths/walls/Walls.cpp": '#include "toolpaths/walls/Walls.h"\n#include "toolpaths/Group.h"\n',
            "planning/Plan.h": '#include "toolpaths/walls/Walls.h"\n',
        }, "--rooms")
        self.assertEqual(rc, 1, out)
        self.assertIn("include cycle between 2 folders: toolpaths/(top), toolpaths/walls", out)
        self.assertIn('toolpaths/(top) -> toolpaths/walls: toolpaths/Group.h:1: #include "toolpaths/walls/Walls.h"',
                      out)
        self.assertNotIn("planning", out)

    def test_rooms_of_different_stages_are_not_compared(self):
        rc, out = run({
            "mixing/color/Color.h": '#include "gcode/out/Writer.h"\n',
            "gcode/out/Writer.h": '#include "mixing/color/Color.h"\n',
        }, "--rooms")
        self.assertEqual(rc, 0, out)

    def test_folder_with_more_than_30_files_fails(self):
        files = {f"toolpaths/F{i}.h": "#pragma once\n" for i in range(31)}
        files.update({f"mixing/color/C{i}.cpp": "\n" for i in range(30)})
        files["mixing/color/notes.txt"] = "not C++\n"
        rc, out = run(files, "--sizes")
        self.assertEqual(rc, 1, out)
        self.assertIn("toolpaths: 31 C++ files directly", out)
        self.assertNotIn("mixing", out)
        del files["toolpaths/F30.h"]
        rc, out = run(files, "--sizes")
        self.assertEqual(rc, 0, out)

    def test_clipper_outside_geometry_fails(self):
        tree = {
            "geometry/PolygonOps.cpp": "#include <polyclipping/clipper.hpp>\nClipperLib::Clipper c;\n",
            "slicing/Slicer.cpp": '#include "geometry/PolygonOps.h"\n',
        }
        rc, out = run(tree, "--clipper")
        self.assertEqual(rc, 0, out)
        tree["slicing/Slicer.cpp"] += "double a = ClipperLib::Area(p);\n"
        tree["mesh/Mesh.h"] = "#include <polyclipping/clipper.hpp>\n"
        rc, out = run(tree, "--clipper")
        self.assertEqual(rc, 1, out)
        self.assertIn("slicing/Slicer.cpp:2: double a = ClipperLib::Area(p);", out)
        self.assertIn("mesh/Mesh.h:1: #include <polyclipping/clipper.hpp>", out)
        self.assertNotIn("geometry/", out.split("\n", 1)[1])

    def test_not_a_directory(self):
        proc = subprocess.run([sys.executable, str(SCRIPT), "/nonexistent/engine"], capture_output=True, text=True)
        self.assertEqual(proc.returncode, 2)
        proc = subprocess.run([sys.executable, str(SCRIPT), "--nonsense", str(SCRIPT.parent)], capture_output=True,
                              text=True)
        self.assertEqual(proc.returncode, 2)


if __name__ == "__main__":
    unittest.main()
