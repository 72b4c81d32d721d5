// The ParaView view script (io/paraview_view_script.h), read back by Python itself: the whole
// script compiles, and its settings block, parsed by Python's literal parser, holds what the run
// gave (a title with quotes, a backslash and a line break unchanged, the unit, the profile, the
// view direction normalised). ParaView running the script is scripts/paraview-check.sh's test.
#include "io/paraview_view_script.h"
#include "scratch_dir.h"

#include <gtest/gtest.h>

#include <cstdlib>

namespace tightfit {
namespace {

class ViewScript : public ScratchDir {
 protected:
  // Runs python3 with `code` (which reads the script at sys.argv[1]); returns what it printed.
  std::string python(const std::string& code, const std::string& script) {
    std::ofstream(path("probe.py")) << code;
    const std::string command =
        "python3 " + path("probe.py") + " " + script + " > " + path("printed.txt") + " 2>&1";
    EXPECT_EQ(std::system(command.c_str()), 0) << read_text(path("printed.txt"));
    return read_text(path("printed.txt"));
  }
};

TEST_F(ViewScript, SettingsReadBackByPython) {
  ViewScriptSettings s;
  s.title = "it's a \"T\" \\ garment\non a cylinder";
  s.in_mmHg = true;
  s.body_has_pressure = false;
  s.angular_profile_csv = "pressure_theta.csv";
  s.view_direction = Vec3(0, 2, 0);
  s.view_up = Vec3(0, 0, 3);
  write_paraview_view_script(path("view.py"), s);
  const std::string printed = python(
      "import ast, sys\n"
      "text = open(sys.argv[1]).read()\n"
      "compile(text, sys.argv[1], 'exec')\n"  // the whole script is Python
      "start = text.index('SETTINGS = {')\n"
      "settings = ast.literal_eval(text[start + 11:text.index('\\n}\\n', start) + 2])\n"
      "for key in ('title', 'garment', 'body', 'body_has_pressure', 'in_mmHg',\n"
      "            'angular_profile', 'view_direction', 'view_up', 'pascal_per_mmHg'):\n"
      "    print(key, repr(settings[key]))\n",
      path("view.py"));
  EXPECT_EQ(printed,
            "title 'it\\'s a \"T\" \\\\ garment\\non a cylinder'\n"
            "garment 'garment.pvd'\n"
            "body 'body.pvd'\n"
            "body_has_pressure False\n"
            "in_mmHg True\n"
            "angular_profile 'pressure_theta.csv'\n"
            "view_direction (0.0, 1.0, 0.0)\n"
            "view_up (0.0, 0.0, 1.0)\n"
            "pascal_per_mmHg 133.322387415\n");
}

TEST_F(ViewScript, NoProfileIsNone) {
  write_paraview_view_script(path("view.py"), ViewScriptSettings{});
  EXPECT_NE(read_text(path("view.py")).find("'angular_profile': None,"), std::string::npos);
  EXPECT_NE(read_text(path("view.py")).find("'in_mmHg': False,"), std::string::npos);
}

TEST_F(ViewScript, RefusesAViewAlongUpAndAMissingFolder) {
  ViewScriptSettings s;
  s.view_direction = Vec3(0, 0, -1);
  EXPECT_THROW(write_paraview_view_script(path("view.py"), s), std::invalid_argument);
  EXPECT_THROW(write_paraview_view_script(path("no/such/folder/view.py"), ViewScriptSettings{}),
               std::runtime_error);
}

}  // namespace
}  // namespace tightfit
