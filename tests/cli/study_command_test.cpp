// `graspsim study run / collect`: bad input gets one line and exit 2 with nothing written; a small
// study runs on two processes into results.csv; a run interrupted (a case gone, another
// half-written; and a run killed with its case processes) and restarted ends with the same table; shards run by hand and collected give the
// same table as one run; a case the reader refuses is recorded as failed and the others run.

#include "cli_process.h"

#include <gtest/gtest.h>

#include <csignal>
#include <sstream>

namespace fs = std::filesystem;
using graspsim::testing::RunResult;
using graspsim::testing::slurp;
using StudyCommand = graspsim::testing::CliProcess;

namespace {

// The ball clutch shortened to 0.2 s (release at 0.05 s, the pull from 0.12 s), four cases.
// Each value is accepted alone (against the base's 0.9 / 0.7), but static friction 0.75 with
// dynamic 0.8 is refused by the reader: cases 0 and 1 fail, 2 and 3 run.
const std::string kStudy = R"(name: tiny
base: ball-clutch
set:
  controller.approach_time: 0.05
  simulation.settle_time: 0.1
  simulation.duration: 0.2
  perturbations: {f1: {force: [0, -9.5, 0], start: 0.12, duration: 0.08}}
  perturbation: f1
axes:
  contact.static_friction: [0.75, 0.9]
  contact.dynamic_friction: [0.8]
  mode: [full, approx]
measures: [held, object_displacement_m, wall_time_s, q_at_engage_n]
)";

// results.csv without its wall_time_s column: the only one that differs between runs.
std::string dropWallTime(const std::string& csv) {
    std::istringstream in(csv);
    std::string line, header, out;
    std::getline(in, header);
    int column = 0;
    for (std::size_t at = 0, next; (next = header.find(',', at)) != std::string::npos; at = next + 1, ++column) {
        if (header.substr(at, next - at) == "wall_time_s") break;
    }
    in.seekg(0);
    while (std::getline(in, line)) {
        std::vector<std::string> fields;
        std::string field;
        std::istringstream cells(line);
        while (std::getline(cells, field, ',')) fields.push_back(field);
        fields.erase(fields.begin() + column);
        for (std::size_t i = 0; i < fields.size(); ++i) out += (i ? "," : "") + fields[i];
        out += "\n";
    }
    return out;
}

}  // namespace

TEST_F(StudyCommand, BadInputGetsOneLineAndWritesNothing) {
    const auto expectRefused = [&](const std::string& study, const std::string& extra, const char* fragment) {
        const std::string path = write("bad.yaml", study);
        const RunResult r = run("study run " + path + " --out " + (dir_ / "out").string() + extra);
        EXPECT_EQ(r.exitCode, 2) << r.err;
        EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
        EXPECT_NE(r.err.find(fragment), std::string::npos) << r.err;
        EXPECT_FALSE(fs::exists(dir_ / "out")) << r.err;
    };
    const auto with = [](const std::string& from, const std::string& to) {
        std::string text = kStudy;
        text.replace(text.find(from), from.size(), to);
        return text;
    };
    expectRefused(with("contact.static_friction: [0.75, 0.9]", "contact.grip: [0.75, 0.9]"), "",
                  "bad.yaml:10: axis 'contact.grip': field 'contact.grip' is not accepted");
    expectRefused(with("[0.75, 0.9]", "[0.9, high]"), "", "field 'contact.static_friction' value 'high' is not accepted");
    expectRefused(with("[0.75, 0.9]", "[0.9, -2]"), "", "value '-2' is not accepted");
    expectRefused(with("[0.75, 0.9]", "[]"), "", "axis 'contact.static_friction' is empty");
    expectRefused(kStudy, " --shard 5/4", "--shard: value '5/4' is not accepted");
    expectRefused(kStudy, " --jobs 0", "--jobs: value 0 is not accepted");
}

TEST_F(StudyCommand, FolderOfAnotherStudyIsLeftAsItWas) {
    fs::create_directories(dir_ / "out");
    const std::string path = write("other.yaml", "name: other\nbase: phone-pinch\naxes: {mode: [full]}\nmeasures: [held]\n");
    ASSERT_EQ(run("study collect " + (dir_ / "out").string()).exitCode, 2);  // not a study folder
    // Prepare the folder as the other study's (a shard whose cases are all another shard's).
    ASSERT_EQ(run("study run " + path + " --out " + (dir_ / "out").string() + " --shard 1/2").exitCode, 0);
    const std::string before = slurp(dir_ / "out/study.json");
    const RunResult r = run("study run " + write("s.yaml", kStudy) + " --out " + (dir_ / "out").string());
    EXPECT_EQ(r.exitCode, 2);
    EXPECT_NE(r.err.find("holds the results of another study ('other'"), std::string::npos) << r.err;
    EXPECT_EQ(slurp(dir_ / "out/study.json"), before);
    EXPECT_FALSE(fs::exists(dir_ / "out/cases/0000"));
}

TEST_F(StudyCommand, RunResumesAndShardsCollectToTheSameTable) {
    const std::string study = write("s.yaml", kStudy);
    const fs::path whole = dir_ / "whole", sharded = dir_ / "sharded";
    const RunResult first = run("study run " + study + " --out " + whole.string() + " --jobs 2");
    ASSERT_EQ(first.exitCode, 0) << first.err;
    EXPECT_EQ(first.err, "") << "no progress bar off a terminal";
    const std::string table = slurp(whole / "results.csv");
    std::istringstream rows(table);
    std::string header, row;
    std::getline(rows, header);
    EXPECT_EQ(header, "case,contact.static_friction,contact.dynamic_friction,mode,status,held,object_displacement_m,wall_time_s,q_at_engage_n,error");
    int count = 0;
    while (std::getline(rows, row)) ++count;
    ASSERT_EQ(count, 4) << table;
    // The error column holds the reader's one line (CSV-quoted only when it contains a comma).
    const std::size_t failed = table.find("0,0.75,0.8,full,failed,,,,,");
    ASSERT_NE(failed, std::string::npos) << table;
    EXPECT_NE(table.find("field 'contact.dynamic_friction' value '0.8' is not accepted", failed), std::string::npos) << table;
    EXPECT_NE(table.find("2,0.9,0.8,full,ok,true,"), std::string::npos) << table;
    EXPECT_NE(table.find("3,0.9,0.8,approx,ok,true,"), std::string::npos) << table;

    // Plots of each measure, or one line saying why there are none.
    EXPECT_TRUE(fs::exists(whole / "plots/object_displacement_m.png") || first.out.find("plots skipped") != std::string::npos)
        << first.out;
    ::setenv("GRASPSIM_PYTHON", "/nonexistent/python3", 1);
    const RunResult noPython = run("study collect " + whole.string());
    ::unsetenv("GRASPSIM_PYTHON");
    EXPECT_EQ(noPython.exitCode, 0);
    EXPECT_NE(noPython.out.find("plots skipped: no Python interpreter at /nonexistent/python3"), std::string::npos) << noPython.out;

    // Interrupted: case 2 never committed, case 3 half-written (its temporary folder, no case.json).
    const auto case1Time = fs::last_write_time(whole / "cases/0001/case.json");
    fs::remove_all(whole / "cases/0002");
    fs::rename(whole / "cases/0003", whole / "cases/0003.tmp-99999");
    fs::remove(whole / "cases/0003.tmp-99999/case.json");
    const RunResult missing = run("study collect " + whole.string());
    EXPECT_EQ(missing.exitCode, 5);
    EXPECT_NE(missing.out.find("missing: 2, 3"), std::string::npos) << missing.out;
    ASSERT_EQ(run("study run " + study + " --out " + whole.string() + " --jobs 2").exitCode, 0);
    EXPECT_EQ(dropWallTime(slurp(whole / "results.csv")), dropWallTime(table));
    EXPECT_EQ(fs::last_write_time(whole / "cases/0001/case.json"), case1Time) << "a finished case is not run again";
    EXPECT_FALSE(fs::exists(whole / "cases/0003.tmp-99999"));

    // Killed for real (the run and its case processes, one process group) while cases 2 and 3
    // run (0 and 1 fail at once, without a process), then restarted: the same table.
    const fs::path killed = dir_ / "killed";
    const std::string start = "setsid " + std::string(GRASPSIM_CLI_PATH) + " study run " + study + " --out " + killed.string() +
                              " --jobs 2 >/dev/null 2>&1 & echo $! > " + (dir_ / "pid").string();
    ASSERT_EQ(std::system(("sh -c '" + start + "'").c_str()), 0);
    const auto running = [&] {
        if (!fs::exists(killed / "cases/0001/case.json")) return false;
        for (const auto& entry : fs::directory_iterator(killed / "cases")) {
            if (entry.path().filename().string().rfind("0003.tmp-", 0) == 0) return true;
        }
        return false;
    };
    for (int i = 0; i < 600 && !running(); ++i) ::usleep(20000);
    const int pid = std::stoi(slurp(dir_ / "pid"));
    ASSERT_EQ(::kill(-pid, SIGKILL), 0);
    ::usleep(200000);
    ASSERT_FALSE(fs::exists(killed / "results.csv")) << "killed before the end";
    EXPECT_FALSE(fs::exists(killed / "cases/0003/case.json"));
    ASSERT_EQ(run("study run " + study + " --out " + killed.string() + " --jobs 2").exitCode, 0);
    EXPECT_EQ(dropWallTime(slurp(killed / "results.csv")), dropWallTime(table));

    // Three shards by hand, then collect.
    for (const char* shard : {"0/3", "1/3", "2/3"}) {
        const RunResult r = run("study run " + study + " --out " + sharded.string() + " --shard " + shard);
        ASSERT_EQ(r.exitCode, 0);
        EXPECT_FALSE(fs::exists(sharded / "results.csv"));
        // Shard 0/3 holds cases 0 (failed) and 3 (ok), counted in the summary's words.
        const std::string counted = "shard 0/3: 2 cases (0 already finished, 2 run now), 1 failed; merge the shards with ";
        if (std::string(shard) == "0/3") EXPECT_EQ(r.out, counted + "`graspsim study collect " + sharded.string() + "`\n");
    }
    const RunResult collected = run("study collect " + sharded.string());
    EXPECT_EQ(collected.exitCode, 0) << collected.out;
    // No incomplete case: the summary's words are those it always had.
    const std::string summary = "study 'tiny': 4 cases, 2 ok, 2 failed, 0 missing; table in " + sharded.string() +
                                "/results.csv\nfailed (see their error column): 0, 1\n";
    EXPECT_EQ(collected.out.substr(0, summary.size()), summary) << collected.out;
    EXPECT_EQ(dropWallTime(slurp(sharded / "results.csv")), dropWallTime(table));
}

// command: capacity. Each case is `graspsim capacity` on its scenario: the phone's -y and x ramps
// (8 N/s, 0.6 s) give in results.csv the figures the command gives run by hand with the same
// options (the second method: the same measurement outside the study), and the phone made twenty
// times heavier, which its pinch drops before the load, is an incomplete case naming why, counted
// as incomplete in the summary. A case's stdout.txt names its committed folder.
TEST_F(StudyCommand, ACapacityStudyTablesTheFiguresTheCommandGives) {
    const std::string study = write("cap.yaml", "name: cap\ncommand: capacity\nbase: phone-pinch\nset: {rate: 8, max_duration: 0.6}\n"
                                                "axes:\n  object.mass: [0.1, 2.0]\n  direction: [-y, x]\n"
                                                "measures: [slip_onset_n, drop_n, grip_force_start_n]\n");
    const std::string out = (dir_ / "st").string();
    const RunResult r = run("study run " + study + " --out " + out + " --jobs 2");
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The summary counts and lists the cases in the status column's words.
    const std::string summary = "study 'cap': 4 cases, 2 ok, 2 incomplete, 0 failed, 0 missing; table in " + out +
                                "/results.csv\nincomplete (stopped early; see their error column): 2, 3\n";
    EXPECT_EQ(r.out.substr(0, summary.size()), summary) << r.out;
    // What the case printed names the folder it is kept in, not the one it ran in.
    const std::string printed = slurp(fs::path(out) / "cases/0000/stdout.txt");
    const std::string ending = "; files in " + out + "/cases/0000\n";
    EXPECT_EQ(printed.substr(printed.size() - std::min(printed.size(), ending.size())), ending) << printed;
    std::istringstream csv(slurp(fs::path(out) / "results.csv"));
    std::string line;
    std::getline(csv, line);
    EXPECT_EQ(line, "case,object.mass,direction,status,slip_onset_n,drop_n,grip_force_start_n,error");
    for (const char* direction : {"-y", "x"}) {
        const std::string single = (dir_ / (std::string("single") + direction)).string();
        ASSERT_EQ(run(std::string("capacity phone-pinch --rate 8 --max-duration 0.6 --direction ") + direction + " --out " + single).exitCode, 0);
        const std::string json = slurp(fs::path(single) / "capacity.json");
        const auto number = [&](const std::string& key) {
            const std::size_t at = json.find("\"" + key + "\": ");
            return at == std::string::npos ? std::string("?") : json.substr(at + key.size() + 4, json.find_first_of(",\n", at) - at - key.size() - 4);
        };
        std::getline(csv, line);
        EXPECT_EQ(line, std::string(direction == std::string("-y") ? "0" : "1") + ",0.1," + direction + ",ok," + number("slip_onset_n") +
                            "," + number("drop_n") + "," + number("grip_force_start_n") + ",")
            << json;
    }
    for (const char* direction : {"-y", "x"}) {
        std::getline(csv, line);
        EXPECT_EQ(line.rfind(std::string(direction == std::string("-y") ? "2" : "3") + ",2.0," + direction + ",incomplete,,,,", 0), 0u) << line;
        EXPECT_NE(line.find("the grasp does not hold the object at the load's start"), std::string::npos) << line;
    }
}
