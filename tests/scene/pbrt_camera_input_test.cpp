// pbrt input that names no transform or camera (a LookAt at its own eye, a Rotate about no axis, a field of view
// outside (0, 180)) is refused in pbrt's words, naming the file, the line and the directive or parameter; a
// byte-order mark at the start of a file is skipped.
#include <gtest/gtest.h>

#include <string>

#include "io/load_diagnostics.h"
#include "scene/loaders/pbrt/pbrt_loader.h"
#include "scene/scene_test_files.h"
#include "support/pbrt_text.h"

namespace candela {
namespace {

constexpr const char* kTriangle =
    "Shape \"trianglemesh\" \"point3 P\" [0 0 0  1 0 0  0 1 0] \"integer indices\" [0 1 2]\n";

using test::pbrt::loadError;

TEST(PbrtCameraInput, ALookAtWithoutADirectionIsRefusedNamingTheLine) {
  EXPECT_EQ(loadError("\nLookAt 1 2 3  1 2 3  0 1 0\nCamera \"perspective\"\nWorldBegin\n"),
            "test.pbrt:2: LookAt: the eye and the point looked at are the same point");
  EXPECT_EQ(loadError("LookAt 0 0 0  0 0 1  0 0 2\nCamera \"perspective\"\nWorldBegin\n"),
            "test.pbrt:1: LookAt: the up vector is zero or parallel to the view direction");
}

TEST(PbrtCameraInput, ARotateAboutNoAxisIsRefusedNamingTheLine) {
  EXPECT_EQ(loadError("Camera \"perspective\"\nWorldBegin\nRotate 30 0 0 0\n"),
            "test.pbrt:3: Rotate: the axis has no direction (it is zero or not finite)");
}

TEST(PbrtCameraInput, AFieldOfViewOutsideZeroTo180IsRefusedNamingTheParameter) {
  for (const char* fov : {"0", "-10", "180", "400"}) {
    const std::string error =
        loadError(std::string("Camera \"perspective\" \"float fov\" ") + fov + "\nWorldBegin\n" + kTriangle);
    EXPECT_EQ(error.rfind("test.pbrt:1: Camera 'fov' ", 0), 0u) << error;
    EXPECT_NE(error.find("must lie between 0 and 180 degrees"), std::string::npos) << error;
  }
}

TEST(PbrtCameraInput, ScreenWindowErrorsSpeakPbrt) {
  const std::string error = loadError("Camera \"perspective\" \"float screenwindow\" [-3e38 3e38 -1 1]\nWorldBegin\n" +
                                      std::string(kTriangle));
  EXPECT_EQ(error,
            "test.pbrt:1: Camera 'screenwindow' (or 'frameaspectratio'): the window is empty or its size is not "
            "finite");
}

// What the scene's repair would refuse in a camera is refused here first, naming the pbrt parameter rather than
// a field of candela's scene file.
TEST(PbrtCameraInput, CamerasBeyondTheCoordinateLimitsAreRefusedInPbrtsTerms) {
  const std::string world = "WorldBegin\n" + std::string(kTriangle);
  EXPECT_EQ(loadError("Camera \"orthographic\" \"float screenwindow\" [-1 1 -1e20 1e20]\n" + world),
            "test.pbrt:1: Camera 'screenwindow': the window gives no field of view, or a size or shift beyond 1e9");
  EXPECT_EQ(loadError("Camera \"perspective\" \"float lensradius\" 1e30\n" + world),
            "test.pbrt:1: Camera 'lensradius' 1000000015047466219876688855040.000000: it must lie between 0 and 1e9");
  EXPECT_EQ(loadError("Camera \"perspective\" \"float focaldistance\" -1\n" + world),
            "test.pbrt:1: Camera 'focaldistance' -1.000000: it must lie between 0 and 1e9");
  EXPECT_EQ(loadError("LookAt 3e38 0 0  0 0 0  0 1 0\nCamera \"perspective\"\n" + world),
            "test.pbrt:2: Camera: the camera transform (the CTM at the Camera directive) places the camera beyond 1e9");
  EXPECT_EQ(loadError("Translate 1e20 0 0\nCamera \"perspective\"\n" + world),
            "test.pbrt:2: Camera: the camera transform (the CTM at the Camera directive) places the camera beyond 1e9");
}

TEST(PbrtCameraInput, AByteOrderMarkIsSkippedInTheMainFileAndInIncludes) {
  test::TempFolder folder;
  const std::string bom = "\xEF\xBB\xBF";
  folder.write("part.pbrt", bom + kTriangle);
  const std::string main =
      folder.write("main.pbrt", bom + "Camera \"perspective\"\nWorldBegin\nInclude \"part.pbrt\"\n");
  LoadWarnings warnings;
  EXPECT_EQ(loadPbrt(main, warnings).triangleCount(), 1u);
  EXPECT_EQ(loadError(bom + "Camera \"perspective\"\nWorldBegin\n" + kTriangle), "(no error)");
}

}  // namespace
}  // namespace candela
