#include "progress_meter.h"

#include <unistd.h>

#include <cmath>
#include <cstdio>

namespace graspsim::cli {

ProgressMeter::ProgressMeter(std::string label, bool quiet)
    : label_(std::move(label)), shown_(!quiet && ::isatty(STDERR_FILENO)) {}

ProgressMeter::~ProgressMeter() { finish(); }

std::string ProgressMeter::formatDuration(double seconds) {
    const long s = std::lround(std::max(0.0, seconds));
    char text[32];
    if (s >= 3600) std::snprintf(text, sizeof text, "%ldh%02ldm", s / 3600, (s % 3600) / 60);
    else if (s >= 60) std::snprintf(text, sizeof text, "%ldm%02lds", s / 60, s % 60);
    else std::snprintf(text, sizeof text, "%lds", s);
    return text;
}

double ProgressMeter::estimateTimeLeft(double elapsed, double done, double total) {
    if (!(done > 0) || !(total > 0)) return -1;
    return elapsed / done * std::max(0.0, total - done);
}

void ProgressMeter::update(double done, double total, const std::string& detail) {
    if (!shown_) return;
    const Clock::time_point now = Clock::now();
    const bool last = done >= total;
    if (!last && drawn_ && now - lastDraw_ < std::chrono::milliseconds(200)) return;
    lastDraw_ = now;
    const double elapsed = std::chrono::duration<double>(now - start_).count();
    const double left = estimateTimeLeft(elapsed, done, total);
    char percent[16];
    std::snprintf(percent, sizeof percent, "%3.0f%%", total > 0 ? 100 * std::min(1.0, done / total) : 0.0);
    std::string line = label_ + " " + percent + (detail.empty() ? "" : "  " + detail) + "  " + formatDuration(elapsed) + " elapsed";
    // The first moments say little about the pace.
    if (left >= 0 && elapsed >= 1) line += ", about " + formatDuration(left) + " left";
    const std::size_t width = line.size();
    if (width < lastWidth_) line.append(lastWidth_ - width, ' ');  // wipe the longer line before
    lastWidth_ = width;
    std::fprintf(stderr, "\r%s", line.c_str());
    std::fflush(stderr);
    drawn_ = true;
}

void ProgressMeter::finish() {
    if (!drawn_) return;
    std::fprintf(stderr, "\n");
    drawn_ = false;
}

}  // namespace graspsim::cli
