// The replay page in a real browser: headless Chromium (software WebGL) loads replay.html of a
// short approx run; the page's own state (#replay-state) must report every sample, every body drawn,
// WebGL up and no console error; a screenshot by `graspsim view --png` must show the bodies:
// non-background pixels in the 3-D view, among them the hand's skin and the phone's colour.
// LABEL browser: needs Debian's chromium (and takes some seconds).

#include "graspsim/viewer/still_picture.h"

#include "scratch_folder.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>
#include <png.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

int runCommand(const std::string& command) {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

struct Image {
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;
    const unsigned char* at(int x, int y) const { return &rgba[4 * (static_cast<std::size_t>(y) * width + x)]; }
};

Image readPng(const fs::path& path) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    Image out;
    if (!png_image_begin_read_from_file(&image, path.c_str())) return out;
    image.format = PNG_FORMAT_RGBA;
    out.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, out.rgba.data(), 0, nullptr)) return {};
    out.width = static_cast<int>(image.width);
    out.height = static_cast<int>(image.height);
    return out;
}

class ReplayBrowser : public graspsim::testing::ScratchFolder {
protected:
    // The phone pinch with approach and settling shortened, so the approximation engages at about 0.22 s.
    fs::path simulateShortApproxRun() {
        std::string text = slurp(fs::path(GRASPSIM_SOURCE_DIR) / "models/scenarios/phone-pinch.yaml");
        for (const auto& [from, to] : {std::pair<std::string, std::string>{"approach_time: 0.5 ", "approach_time: 0.05"},
                                       {"settle_time: 1.0 ", "settle_time: 0.15"}}) {
            text.replace(text.find(from), from.size(), to);
        }
        std::ofstream(dir_ / "short.yaml") << text;
        const fs::path out = dir_ / "run";
        const std::string cli = GRASPSIM_CLI_PATH;
        EXPECT_EQ(runCommand(cli + " simulate " + (dir_ / "short.yaml").string() + " --mode approx --duration 0.4 --view --out " +
                             out.string() + " > /dev/null"),
                  0);
        return out;
    }
};

TEST_F(ReplayBrowser, PageReportsEveryFrameAndBodyWithoutErrors) {
    const fs::path out = simulateShortApproxRun();
    ASSERT_TRUE(fs::exists(out / "replay.html"));
    const std::string dom = (dir_ / "dom.html").string();
    const std::string command = graspsim::viewer::findChromium() +
                                " --headless --no-sandbox --use-gl=swiftshader --enable-unsafe-swiftshader --no-first-run"
                                " --user-data-dir=" + (dir_ / "profile").string() +
                                " --virtual-time-budget=10000 --window-size=900,600 --dump-dom 'file://" +
                                fs::absolute(out / "replay.html").string() + "?t=0.3' > " + dom + " 2> /dev/null";
    ASSERT_EQ(runCommand(command), 0);
    const std::string page = slurp(dom);
    EXPECT_NE(page.find("<title>graspsim replay: ready</title>"), std::string::npos) << page.substr(0, 300);
    const std::size_t start = page.find("id=\"replay-state\"");
    ASSERT_NE(start, std::string::npos);
    const std::size_t open = page.find('{', start), close = page.find('}', open);
    const nlohmann::json state = nlohmann::json::parse(page.substr(open, close - open + 1));
    const std::string trajectory = slurp(out / "trajectory.csv");
    const long samples = std::count(trajectory.begin(), trajectory.end(), '\n') - 1;
    EXPECT_EQ(state["frames"].get<long>(), samples);
    EXPECT_GT(state["bodies"].get<int>(), 10);
    EXPECT_EQ(state["drawn"], state["bodies"]);
    EXPECT_EQ(state["webgl"], true);
    EXPECT_EQ(state["errors"], 0);
    EXPECT_NEAR(state["time"].get<double>(), 0.3, 1e-9);
    // The page shows the engaged constraint at 0.3 s (engaged from about 0.22 s).
    EXPECT_NE(page.find("approximation engaged"), std::string::npos);
}

TEST_F(ReplayBrowser, StillPictureShowsTheHandAndTheObject) {
    const fs::path out = simulateShortApproxRun();
    const std::string cli = GRASPSIM_CLI_PATH;
    ASSERT_EQ(runCommand(cli + " view " + out.string() + " --png 0.3 --size 900x600 > /dev/null"), 0);
    const Image image = readPng(out / "replay.png");
    ASSERT_EQ(image.width, 900);
    ASSERT_EQ(image.height, 600);
    // The 3-D view is everything above the 64-pixel control bar; its background is #f4f4f2.
    long foreground = 0, skin = 0, phone = 0;
    for (int y = 0; y < image.height - 64; ++y) {
        for (int x = 0; x < image.width; ++x) {
            const unsigned char* p = image.at(x, y);
            const int r = p[0], g = p[1], b = p[2];
            if (std::abs(r - 0xf4) + std::abs(g - 0xf4) + std::abs(b - 0xf2) > 24) ++foreground;
            if (r > 120 && r > g + 15 && g > b + 10) ++skin;        // lit or shaded skin (#e0b49a)
            if (b > r + 10 && r < 110 && g < 130) ++phone;         // the dark blue-grey phone (#34495e)
        }
    }
    const long pixels = static_cast<long>(image.width) * (image.height - 64);
    EXPECT_GT(foreground, pixels / 50) << "foreground " << foreground;
    EXPECT_GT(skin, 2000) << "the hand is not drawn";
    EXPECT_GT(phone, 500) << "the phone is not drawn";
}

}  // namespace
