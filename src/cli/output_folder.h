#pragma once
// The --out folder of a command: created and tried with a file before the run (so that a path
// that cannot be created, or a folder that refuses files, is refused before any work), and
// removed again if the run fails before anything was written into it, so that a failed run
// leaves no folder behind. Only what this object created goes, and only while empty: a folder
// that existed before, or holds files, stays as it is. So does an interrupted run (SIGINT,
// SIGTERM, SIGHUP), once removeFoldersOnInterrupt() is installed.

#include <string>

namespace graspsim::cli {

class OutputFolder {
public:
    // Creates `path` and any missing parents, then creates and removes a file in it. Throws
    // InputError "--out: folder '<path>' cannot be created or written (<reason>)", having
    // removed what it created.
    explicit OutputFolder(const std::string& path);
    // Removes the folders it created, leaf first, while they are empty, unless keep() was called.
    ~OutputFolder();
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    // The run gave results: the folder stays (it is about to be written).
    void keep() { kept_ = true; }

private:
    void removeCreated() const;

    std::string path_;
    std::string topCreated_;  // the outermost folder this created; empty if `path` existed
    bool kept_ = false;
    int interruptSlot_ = -1;  // where the interrupt handler finds the folders this created
};

// Installs handlers for SIGINT, SIGTERM (Slurm's scancel and time limit) and SIGHUP that remove
// the folders every live OutputFolder created, leaf first and only while empty, say so in one
// line on stderr, and then end the process by the same signal (so a calling shell or study
// runner sees it was interrupted). A folder that already holds files stays, named as holding
// part of the results.
void removeFoldersOnInterrupt();

}  // namespace graspsim::cli
