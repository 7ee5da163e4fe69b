#include "graspsim/io/atomic_file.h"

#include "graspsim/error.h"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <unistd.h>

namespace graspsim::io {

namespace {

std::string makeTemporaryName(const std::string& path) {
    // The process id keeps two concurrent runs writing the same target from sharing a temp file.
    return path + ".tmp-" + std::to_string(::getpid());
}

}  // namespace

void writeFileAtomically(const std::string& path, const std::string& contents) {
    const std::string tmp = makeTemporaryName(path);
    {
        std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
        if (!out) {
            throw InputError(path + ": cannot write output file (" + std::strerror(errno) +
                             "); give a path in a writable folder");
        }
        out << contents;
        out.flush();
        if (!out) {
            out.close();
            std::remove(tmp.c_str());
            throw InputError(path + ": writing failed (" + std::strerror(errno) + ")");
        }
    }
    std::error_code ec;
    std::filesystem::rename(tmp, path, ec);
    if (ec) {
        std::remove(tmp.c_str());
        throw InputError(path + ": cannot replace output file (" + ec.message() + ")");
    }
}

void removeStaleFile(const std::string& path) {
    std::error_code error;
    std::filesystem::remove(path, error);
    if (error) throw InputError(path + ": a file of an earlier run cannot be removed (" + error.message() + ")");
}

std::string readTextFile(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_directory(path, ec)) {
        throw InputError(path + ": is a folder; expected a file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InputError(path + ": cannot open file (" + std::strerror(errno) + ")");
    }
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

}  // namespace graspsim::io
