#include "study_command.h"

#include "number_option.h"
#include "output_folder.h"

#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/study/case_setup.h"
#include "graspsim/study/slurm_job.h"
#include "graspsim/study/study_case.h"
#include "graspsim/study/study_folder.h"
#include "graspsim/study/study_grid_table.h"
#include "graspsim/study/study_plots.h"
#include "graspsim/study/study_runner.h"
#include "graspsim/study/study_table.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>

namespace graspsim::cli {

namespace fs = std::filesystem;

struct StudyCommand::Options {
    std::string study;
    std::string out;
    std::string jobs = "1";
    std::string shard;
    bool retryFailed = false;
    std::string arraySize;
    std::vector<std::string> sbatchArguments;
};

StudyCommand::StudyCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    Options& o = *options_;
    command_ = app.add_subcommand("study", "Parameter sweeps: run a study file's cases locally or on Slurm, and merge their results");
    command_->require_subcommand(1);
    run_ = command_->add_subcommand("run", "Run a study's cases (or one shard of them) on local processes; skips finished cases");
    run_->add_option("study", o.study, "study file (YAML, see models/studies/)")->required();
    run_->add_option("--out", o.out, "output folder: cases/<n>/, results.csv, plots/")->required();
    run_->add_option("--jobs", o.jobs, "cases run at once, each a graspsim process (default 1)");
    run_->add_option("--shard", o.shard, "i/K: run only the cases whose number is i modulo K (0 <= i < K); "
                                         "merge shards with `graspsim study collect`");
    run_->add_flag("--retry-failed", o.retryFailed, "run failed and incomplete cases again (default: keep their record)");
    submit_ = command_->add_subcommand("submit", "Submit a study as a Slurm job array (task i of K runs shard i/K)");
    submit_->add_option("study", o.study, "study file (YAML)")->required();
    submit_->add_option("--out", o.out, "output folder, on a file system the nodes share")->required();
    submit_->add_option("--array-size", o.arraySize, "number of array tasks K (default: the number of cases, at most 100)");
    submit_->add_option("--sbatch-arg", o.sbatchArguments, "an option for sbatch, e.g. --sbatch-arg=--partition=short (repeatable)");
    collect_ = command_->add_subcommand("collect", "Merge a study folder's cases into results.csv and plots; list missing and failed cases");
    collect_->add_option("folder", o.out, "the study's output folder")->required();
}

bool StudyCommand::parsed() const { return command_->parsed(); }

namespace {

// The binary running now, so that every case runs the same graspsim.
std::string findExecutable() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw Error("cannot find the graspsim executable (/proc/self/exe: " + ec.message() + ")");
    return self.string();
}

// A progress bar with an ETA on a terminal; nothing otherwise (logs of batch jobs stay clean).
std::function<void(const study::RunProgress&)> makeProgressBar() {
    if (!::isatty(STDERR_FILENO)) return {};
    return [](const study::RunProgress& p) {
        std::fprintf(stderr, "\r%s", study::formatRunProgress(p).c_str());
        if (p.finished == p.total) std::fprintf(stderr, "\n");
    };
}

// The study file, its base scenarios and every value checked; nothing written.
struct LoadedStudy {
    study::StudySpec spec;
    std::vector<scenario::ScenarioText> bases;
};

LoadedStudy loadStudy(const std::string& path) {
    LoadedStudy loaded{study::loadStudyFile(path), {}};
    loaded.bases = study::readBaseScenarios(loaded.spec);
    study::checkStudyValues(loaded.spec, loaded.bases);
    return loaded;
}

// The cases counted and listed in the words of results.csv's status column.
void printTableSummary(const study::StudySpec& spec, const study::StudyTable& table, const std::string& folder, bool grid) {
    const std::size_t notOk = table.missing.size() + table.incomplete.size() + table.failed.size();
    std::cout << "study '" << spec.name << "': " << table.total << " cases, " << table.total - static_cast<int>(notOk) << " ok, "
              << study::formatFailureCounts(table.incomplete.size(), table.failed.size()) << ", " << table.missing.size()
              << " missing; table in " << folder << "/results.csv"
              << (grid ? " (a grid by base scenario in results.md)" : "") << "\n";
    if (!table.incomplete.empty()) {
        std::cout << "incomplete (stopped early; see their error column): " << study::formatCaseList(table.incomplete) << "\n";
    }
    if (!table.failed.empty()) std::cout << "failed (see their error column): " << study::formatCaseList(table.failed) << "\n";
    if (!table.missing.empty()) {
        std::cout << "missing: " << study::formatCaseList(table.missing)
                  << "; run the study again (or resubmit): finished cases are skipped\n";
    }
}

// results.csv and the plots; returns collect's exit code (5 when cases are missing).
int mergeResults(const study::StudySpec& spec, const std::string& folder) {
    const study::StudyTable table = study::collectStudyTable(spec, folder);
    study::writeStudyTable(folder, table);
    const std::string grid = study::formatGridTable(spec, folder);
    if (!grid.empty()) io::writeFileAtomically(folder + "/results.md", grid);
    printTableSummary(spec, table, folder, !grid.empty());
    const study::PlotOutcome plots = study::drawStudyPlots(folder);
    if (!plots.skipped.empty()) std::cout << plots.skipped << "\n";
    else std::cout << plots.files.size() << " plot(s) in " << folder << "/plots\n";
    return table.missing.empty() ? 0 : 5;
}

}  // namespace

void StudyCommand::checkOptions() const {
    const Options& o = *options_;
    if (run_->parsed()) {
        parseCount(o.jobs, "--jobs");
        if (!o.shard.empty()) study::parseShard(o.shard);
    }
    if (submit_->parsed() && !o.arraySize.empty()) parseCount(o.arraySize, "--array-size");
}

int StudyCommand::run() const {
    checkOptions();
    if (run_->parsed()) return runCases();
    if (submit_->parsed()) return submit();
    return collect();
}

int StudyCommand::runCases() const {
    const Options& o = *options_;
    study::RunSettings settings;
    settings.folder = o.out;
    settings.jobs = parseCount(o.jobs, "--jobs");
    if (!o.shard.empty()) settings.shard = study::parseShard(o.shard);
    settings.retryFailed = o.retryFailed;
    const LoadedStudy loaded = loadStudy(o.study);
    settings.executable = findExecutable();
    OutputFolder folder(o.out);
    study::prepareStudyFolder(o.out, loaded.spec, study::joinBaseTexts(loaded.bases));
    folder.keep();  // a prepared folder (study.json) stays: a failed run resumes in it
    settings.progress = makeProgressBar();
    const study::RunReport report = study::runStudyCases(loaded.spec, loaded.bases, settings);
    if (settings.shard.count > 1) {
        std::cout << "shard " << o.shard << ": " << report.total << " cases (" << report.skipped << " already finished, "
                  << report.ran << " run now), " << study::formatFailureCounts(report.incomplete, report.failed)
                  << "; merge the shards with `graspsim study collect " << o.out << "`\n";
        return 0;
    }
    return mergeResults(loaded.spec, o.out);
}

int StudyCommand::submit() const {
    const Options& o = *options_;
    const LoadedStudy loaded = loadStudy(o.study);
    const int cases = static_cast<int>(study::expandCases(loaded.spec).size());
    const int arraySize = o.arraySize.empty() ? std::min(cases, 100) : std::min(cases, parseCount(o.arraySize, "--array-size"));
    OutputFolder folder(o.out);
    study::prepareStudyFolder(o.out, loaded.spec, study::joinBaseTexts(loaded.bases));
    folder.keep();  // a prepared folder (study.json) stays: a failed submit can be repeated into it
    study::SlurmJob job;
    job.name = loaded.spec.name;
    job.executable = findExecutable();
    job.studyFile = fs::absolute(o.study).lexically_normal().string();
    job.folder = fs::absolute(o.out).lexically_normal().string();
    job.arraySize = arraySize;
    fs::create_directories(job.folder + "/slurm");
    const std::string script = job.folder + "/slurm/study.sbatch";
    io::writeFileAtomically(script, study::formatSbatchScript(job));
    const std::string id = study::submitSlurmJob(script, o.sbatchArguments);
    std::cout << "submitted job array " << id << ": " << arraySize << " task(s) for " << cases << " cases (script "
              << script << ", logs in " << job.folder << "/slurm); when it has run: graspsim study collect " << o.out << "\n";
    return 0;
}

int StudyCommand::collect() const {
    const std::string& folder = options_->out;
    return mergeResults(study::loadFolderStudy(folder), folder);
}

}  // namespace graspsim::cli
