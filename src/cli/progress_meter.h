#pragma once
// A one-line progress display with an estimate of the time left, for commands that run longer
// than a few seconds. It writes to stderr only when stderr is a terminal and --quiet was not
// given, so logs, pipes and tests stay clean.

#include <chrono>
#include <string>

namespace graspsim::cli {

class ProgressMeter {
public:
    // `label` starts the line ("simulating", "validating", ...).
    ProgressMeter(std::string label, bool quiet);
    ProgressMeter(const ProgressMeter&) = delete;
    ProgressMeter& operator=(const ProgressMeter&) = delete;
    ~ProgressMeter();

    // Whether anything is shown (a terminal, not quiet).
    bool isShown() const { return shown_; }
    // Reports `done` of `total` units of work (runs, simulated seconds: any unit in which the work
    // is roughly proportional to time); `detail` follows on the line. Redrawn at most 5 times a second.
    void update(double done, double total, const std::string& detail = "");
    // Ends the line (once; also done by the destructor).
    void finish();

    // "1h02m", "3m05s" or "42s": a time left, to the second.
    static std::string formatDuration(double seconds);
    // The time left after `elapsed` seconds for `done` of `total` units, at the pace so far; < 0 when
    // there is no pace yet (nothing done).
    static double estimateTimeLeft(double elapsed, double done, double total);

private:
    using Clock = std::chrono::steady_clock;
    std::string label_;
    bool shown_ = false;
    bool drawn_ = false;
    Clock::time_point start_ = Clock::now();
    Clock::time_point lastDraw_{};
    std::size_t lastWidth_ = 0;
};

}  // namespace graspsim::cli
