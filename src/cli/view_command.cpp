#include "view_command.h"

#include "number_option.h"

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/viewer/replay_page.h"
#include "graspsim/viewer/still_picture.h"

#include <cmath>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>

namespace graspsim::cli {

struct ViewCommand::Options {
    std::string folder;
    std::string pngTime;
    std::string pngFile;
    std::string size = "1200x800";
};

ViewCommand::ViewCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    Options& o = *options_;
    command_ = app.add_subcommand("view", "Write DIR/replay.html, a 3-D replay of a simulate result that opens in any browser");
    command_->add_option("folder", o.folder, "a result folder (simulate --out)")->required();
    command_->add_option("--png", o.pngTime, "also render the replay at this time (s) as a PNG picture (needs chromium)");
    command_->add_option("--png-file", o.pngFile, "where to write the picture (default DIR/replay.png)");
    command_->add_option("--size", o.size, "picture size in pixels, WIDTHxHEIGHT (default 1200x800)");
}

bool ViewCommand::parsed() const { return command_->parsed(); }

namespace {

viewer::PictureSize parseSize(const std::string& text) {
    const std::string accepted = "use WIDTHxHEIGHT in pixels, each in [200, 4000], e.g. 1200x800";
    const std::size_t x = text.find('x');
    if (x == std::string::npos) throw InputError("--size: value '" + text + "' is not accepted; " + accepted);
    const auto fits = [](double v) { return v >= 200 && v <= 4000 && v == std::floor(v); };
    // Not parseNumber: its message would name only the part ("800x3" of "1200x800x3").
    const auto readPixels = [](const std::string& part) {
        char* end = nullptr;
        const double value = std::strtod(part.c_str(), &end);
        return !part.empty() && *end == '\0' ? value : 0.0;
    };
    const double width = readPixels(text.substr(0, x)), height = readPixels(text.substr(x + 1));
    if (!fits(width) || !fits(height)) throw InputError("--size: value '" + text + "' is not accepted; " + accepted);
    return {static_cast<int>(width), static_cast<int>(height)};
}

// --png-file names where --png's picture goes: alone it would be silently unused, and a folder
// would be found only after replay.html is written and the picture rendered.
void checkPictureFile(const std::string& pngTime, const std::string& pngFile) {
    if (pngFile.empty()) return;
    if (pngTime.empty()) throw InputError("--png-file: value '" + pngFile + "' is not accepted without --png TIME (the picture's time)");
    std::error_code ec;
    if (std::filesystem::is_directory(pngFile, ec)) {
        throw InputError("--png-file: value '" + pngFile + "' is a folder; give the picture's file name, e.g. replay.png");
    }
    std::string extension = std::filesystem::path(pngFile).extension().string();
    for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    if (extension != ".png") {
        throw InputError("--png-file: value '" + pngFile + "' is not accepted; the picture is a PNG: give a name ending in .png");
    }
    const std::filesystem::path parent = std::filesystem::path(pngFile).parent_path();
    if (!parent.empty() && !std::filesystem::is_directory(parent, ec)) {
        throw InputError("--png-file: value '" + pngFile + "': folder '" + parent.string() + "' does not exist; create it or give "
                         "a file in an existing folder");
    }
}

double parsePictureTime(const std::string& text, const viewer::ResultRecord& record) {
    const double end = record.trajectory.back().time;
    char endText[32];
    std::snprintf(endText, sizeof endText, "%g", end);
    const std::string accepted = "the run covers 0 to " + std::string(endText) + " s";
    const double t = parseNumber(text, "--png", accepted);
    if (!(t >= 0 && t <= end)) throw InputError("--png: time " + text + " s is outside the run; " + accepted);
    return t;
}

}  // namespace

int ViewCommand::run() const {
    const Options& o = *options_;
    if (o.pngTime.empty() && command_->count("--size") > 0) {
        throw InputError("--size: value '" + o.size + "' is not accepted without --png TIME (the picture it sizes)");
    }
    const viewer::PictureSize size = parseSize(o.size);
    checkPictureFile(o.pngTime, o.pngFile);
    // Everything is checked before the first file is written.
    const viewer::ResultRecord record = viewer::readResultFolder(o.folder);
    const double time = o.pngTime.empty() ? 0.0 : parsePictureTime(o.pngTime, record);
    if (!o.pngTime.empty()) viewer::findChromium();
    const std::string page = o.folder + "/replay.html";
    io::writeFileAtomically(page, viewer::makeReplayPage(record));
    std::cout << "replay written to " << page << ": open it in a web browser (no server needed)\n";
    if (o.pngTime.empty()) return 0;
    const std::string picture = o.pngFile.empty() ? o.folder + "/replay.png" : o.pngFile;
    viewer::renderStillPicture(page, time, picture, size);
    std::cout << "picture at t = " << time << " s written to " << picture << "\n";
    return 0;
}

}  // namespace graspsim::cli
