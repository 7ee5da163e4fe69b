#include "graspsim/viewer/still_picture.h"

#include "graspsim/error.h"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <vector>

namespace graspsim::viewer {

namespace {

namespace fs = std::filesystem;

bool isExecutable(const std::string& path) { return ::access(path.c_str(), X_OK) == 0 && !fs::is_directory(path); }

// Runs `args` (no shell), its output discarded (Chromium logs freely); returns the exit status.
int runQuietly(const std::vector<std::string>& args) {
    std::vector<char*> argv;
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    const pid_t pid = ::fork();
    if (pid < 0) throw Error("cannot start " + args[0]);
    if (pid == 0) {
        const int null = ::open("/dev/null", O_RDWR);
        ::dup2(null, STDIN_FILENO);
        ::dup2(null, STDOUT_FILENO);
        ::dup2(null, STDERR_FILENO);
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    int status = 0;
    while (::waitpid(pid, &status, 0) < 0) {}
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

bool isPng(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    char signature[8] = {};
    in.read(signature, 8);
    return in && std::string(signature, 8) == "\x89PNG\r\n\x1a\n";
}

// A private profile folder: concurrent Chromiums on one profile wait on each other's lock.
class TemporaryFolder {
public:
    TemporaryFolder() {
        std::string pattern = (fs::temp_directory_path() / "graspsim-chromium-XXXXXX").string();
        if (!::mkdtemp(pattern.data())) throw Error("cannot create a temporary folder in " + fs::temp_directory_path().string());
        path_ = pattern;
    }
    ~TemporaryFolder() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    TemporaryFolder(const TemporaryFolder&) = delete;
    TemporaryFolder& operator=(const TemporaryFolder&) = delete;
    const std::string& getPath() const { return path_; }

private:
    std::string path_;
};

}  // namespace

std::string findChromium() {
    if (const char* given = std::getenv("GRASPSIM_CHROMIUM"); given && *given) {
        if (!isExecutable(given)) throw InputError(std::string("GRASPSIM_CHROMIUM: '") + given + "' is not an executable file");
        return given;
    }
    const char* path = std::getenv("PATH");
    std::string dirs = path ? path : "/usr/bin:/bin";
    for (std::size_t start = 0; start <= dirs.size();) {
        const std::size_t end = dirs.find(':', start);
        const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
        for (const char* name : {"chromium", "chromium-browser"}) {
            const std::string candidate = (dir.empty() ? "." : dir) + "/" + name;
            if (isExecutable(candidate)) return candidate;
        }
        if (end == std::string::npos) break;
        start = end + 1;
    }
    throw InputError("--png needs Chromium, which is not on the PATH; install Debian's chromium (apt-get install chromium) "
                     "or set GRASPSIM_CHROMIUM");
}

void renderStillPicture(const std::string& htmlPath, double time, const std::string& pngPath, const PictureSize& size) {
    const std::string chromium = findChromium();
    const TemporaryFolder profile;
    const std::string temporary = pngPath + ".part.png";
    char timeText[32];
    std::snprintf(timeText, sizeof timeText, "%.9g", time);
    // SwiftShader is Chromium's software GL: headless Chromium has no GPU here, and without
    // --enable-unsafe-swiftshader it refuses WebGL on it, leaving the canvas blank.
    const std::vector<std::string> args = {
        chromium, "--headless", "--no-sandbox", "--disable-gpu-sandbox", "--use-gl=swiftshader", "--enable-unsafe-swiftshader",
        "--hide-scrollbars", "--no-first-run", "--user-data-dir=" + profile.getPath(), "--virtual-time-budget=10000",
        "--window-size=" + std::to_string(size.width) + "," + std::to_string(size.height), "--screenshot=" + temporary,
        "file://" + fs::absolute(htmlPath).string() + "?t=" + timeText};
    std::error_code ec;
    fs::remove(temporary, ec);
    const int status = runQuietly(args);
    if (status != 0 || !isPng(temporary)) {
        fs::remove(temporary, ec);
        throw InputError(chromium + " did not render " + htmlPath + " (exit status " + std::to_string(status) + ")");
    }
    fs::rename(temporary, pngPath, ec);
    if (ec) {
        const std::string why = ec.message();  // before remove() clears ec
        fs::remove(temporary, ec);
        throw InputError(pngPath + ": cannot be written (" + why + ")");
    }
}

}  // namespace graspsim::viewer
