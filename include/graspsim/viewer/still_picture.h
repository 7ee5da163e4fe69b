#pragma once
/// @file
/// Still pictures of a replay page (for reports and the README), rendered by headless Chromium
/// with software WebGL (SwiftShader), so no display or GPU is needed.

#include <string>

namespace graspsim::viewer {

/// Size of a still picture (pixels).
struct PictureSize {
    int width = 1200;
    int height = 800;
};

/// The Chromium executable: $GRASPSIM_CHROMIUM when set, else `chromium` or `chromium-browser`
/// on the PATH.
/// @throws graspsim::InputError saying how to install it when there is none.
std::string findChromium();

/// Renders the replay page `htmlPath` (replay_page.h) at `time` (s; the page shows the last
/// sample at or before it) into the PNG file `pngPath`: written whole or not at all.
/// @throws graspsim::InputError when Chromium is missing, fails, or writes no picture.
void renderStillPicture(const std::string& htmlPath, double time, const std::string& pngPath, const PictureSize& size = {});

}  // namespace graspsim::viewer
