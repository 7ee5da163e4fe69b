#include "urdfdom_parse.h"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <mutex>

namespace graspsim::model {

namespace {

class CapturingOutputHandler : public console_bridge::OutputHandler {
public:
    void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
        if (level < console_bridge::CONSOLE_BRIDGE_LOG_ERROR) return;
        errors += (errors.empty() ? "" : "; ") + text;
    }
    std::string errors;
};

// Installs `handler` at error level for its lifetime and puts the previous handler and level
// back, even if urdfdom throws. The level matters: at LOG_NONE errors would not reach us.
class ScopedOutputHandler {
public:
    explicit ScopedOutputHandler(console_bridge::OutputHandler* handler)
        : previousHandler_(console_bridge::getOutputHandler()), previousLevel_(console_bridge::getLogLevel()) {
        console_bridge::useOutputHandler(handler);
        console_bridge::setLogLevel(console_bridge::CONSOLE_BRIDGE_LOG_ERROR);
    }
    ~ScopedOutputHandler() {
        console_bridge::setLogLevel(previousLevel_);
        console_bridge::useOutputHandler(previousHandler_);
    }
    ScopedOutputHandler(const ScopedOutputHandler&) = delete;
    ScopedOutputHandler& operator=(const ScopedOutputHandler&) = delete;

private:
    console_bridge::OutputHandler* previousHandler_;
    console_bridge::LogLevel previousLevel_;
};

}  // namespace

UrdfdomParse parseWithUrdfdom(const std::string& xml) {
    static std::mutex mutex;
    // console_bridge keeps a pointer to the last handler as its "previous" one, so the handler
    // must outlive this call: a static, guarded by the same mutex.
    static CapturingOutputHandler handler;
    const std::lock_guard<std::mutex> lock(mutex);
    handler.errors.clear();
    UrdfdomParse result;
    {
        const ScopedOutputHandler scope(&handler);
        result.model = urdf::parseURDF(xml);
    }
    result.errors = handler.errors;
    return result;
}

}  // namespace graspsim::model
