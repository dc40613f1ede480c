// End-to-end: `tsf gen` and `tsf render` killed with SIGKILL at random
// moments while they replace a good model. Afterwards the model is the old
// file or the complete new one, never a truncated one; a model and its scene
// sidecar either belong together or `tsf verify --scene` refuses the pair;
// and the temporary files a killed run could not remove are gone after the
// next run.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <random>
#include <thread>

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tests/support/run.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;
using test::kExitBadInput;
using test::kExitOk;
using test::readText;
using test::runTsf;
using test::scratchDir;
using test::writeText;

using Clock = std::chrono::steady_clock;

constexpr int kKills = 12;

// A field of 60 x 60 values (a 2.5 MB STL: its writing takes a while);
// `seed` changes every value, not the size, so two versions of the model have
// the same triangle count (and binary STL size).
std::string field(int seed) {
    std::string csv;
    for (int r = 0; r < 60; ++r) {
        for (int c = 0; c < 60; ++c) csv += (c ? "," : "") + std::to_string(1 + (r * 7 + c * 3 + seed * 11) % 50);
        csv += "\n";
    }
    return csv;
}

int temporaryFiles(const fs::path& dir) {
    int n = 0;
    for (const auto& e : fs::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) ++n;
    return n;
}

// Starts `tsf args...` (no shell in between, so the kill reaches tsf itself).
pid_t startTsf(const std::vector<std::string>& args) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        std::vector<char*> argv;
        static std::string binary = TSF_BINARY;
        argv.push_back(binary.data());
        for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
        argv.push_back(nullptr);
        const int null_fd = ::open("/dev/null", O_WRONLY);
        ::dup2(null_fd, 1);
        ::dup2(null_fd, 2);
        ::execv(TSF_BINARY, argv.data());
        ::_exit(127);
    }
    return pid;
}

// Runs tsf to the end; its wall time.
double timedRun(const std::vector<std::string>& args) {
    const auto t0 = Clock::now();
    const pid_t pid = startTsf(args);
    int status = 0;
    ::waitpid(pid, &status, 0);
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << "status " << status;
    return std::chrono::duration<double>(Clock::now() - t0).count();
}

// Starts tsf, kills it with SIGKILL after `delay_s`, and waits until it and
// anything it started (an OpenSCAD it ran outlives it; this process is their
// subreaper) have ended.
void killAfter(const std::vector<std::string>& args, double delay_s) {
    const pid_t pid = startTsf(args);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay_s));
    ::kill(pid, SIGKILL);
    while (::waitpid(-1, nullptr, 0) > 0) {
    }
}

// The process adopts what a killed tsf leaves running, for the test's length.
struct Subreaper {
    Subreaper() { ::prctl(PR_SET_CHILD_SUBREAPER, 1); }
    ~Subreaper() { ::prctl(PR_SET_CHILD_SUBREAPER, 0); }
};

TEST(KillSafety, GenKilledAnywhereLeavesTheOldModelOrTheNewOneAndNeverAMismatchedSidecar) {
    Subreaper subreaper;
    const fs::path dir = scratchDir(), ref = dir / "reference", work = dir / "work";
    fs::create_directories(ref);
    fs::create_directories(work);
    writeText(dir / "old.csv", field(1));
    writeText(dir / "new.csv", field(2));
    // Both finished outputs, made once without interruption: the only two
    // states a model may be seen in.
    // --no-verify: the run is then mostly writing, where a kill matters (the
    // self-check writes nothing).
    const auto gen = [&](const fs::path& out_dir, const std::string& input) {
        return std::vector<std::string>{"gen", (dir / input).string(), "-o", (out_dir / "m.stl").string(),
                                        "--no-verify", "--cull", "none"};
    };
    ASSERT_EQ(timedRun(gen(ref, "new.csv")) > 0, true);
    const std::string new_stl = readText(ref / "m.stl"), new_scene = readText(ref / "m.stl.scene.json");
    const double full_s = timedRun(gen(work, "old.csv"));
    const std::string old_stl = readText(work / "m.stl"), old_scene = readText(work / "m.stl.scene.json");
    const std::string new_key = readText(ref / "m.key.txt"), new_brf = readText(ref / "m.key.brf");
    const std::string old_key = readText(work / "m.key.txt"), old_brf = readText(work / "m.key.brf");
    ASSERT_NE(old_key, new_key);
    ASSERT_FALSE(old_stl.empty());
    ASSERT_EQ(old_stl.size(), new_stl.size()) << "same size on purpose: only the bytes tell them apart";
    ASSERT_NE(old_stl, new_stl);

    std::mt19937 rng(15);
    std::uniform_real_distribution<double> moment(0.2 * full_s, 1.1 * full_s);
    int seen_new = 0, seen_mismatch = 0, seen_key_mismatch = 0;
    for (int k = 0; k < kKills; ++k) {
        // A good old model, then a run that replaces it is killed.
        writeText(work / "m.stl", old_stl);
        writeText(work / "m.stl.scene.json", old_scene);
        writeText(work / "m.key.txt", old_key);
        writeText(work / "m.key.brf", old_brf);
        killAfter(gen(work, "new.csv"), moment(rng));
        const std::string stl = readText(work / "m.stl"), scene = readText(work / "m.stl.scene.json");
        ASSERT_TRUE(stl == old_stl || stl == new_stl) << "kill " << k << ": a model of " << stl.size() << " bytes";
        ASSERT_TRUE(scene == old_scene || scene == new_scene) << "kill " << k << ": a sidecar of " << scene.size();
        seen_new += stl == new_stl;
        // Keys from another run than the model are named by tsf verify.
        const std::string key = readText(work / "m.key.txt"), brf = readText(work / "m.key.brf");
        ASSERT_TRUE(key == old_key || key == new_key) << "kill " << k;
        ASSERT_TRUE(brf == old_brf || brf == new_brf) << "kill " << k;
        if ((stl == new_stl) != (key == new_key) || (stl == new_stl) != (brf == new_brf)) {
            ++seen_key_mismatch;
            const auto v = runTsf("verify " + (work / "m.stl").string());
            EXPECT_EQ(v.exit_code, kExitBadInput) << v.output;
            EXPECT_NE(v.output.find("is the key of another version of m.stl"), std::string::npos) << v.output;
        }
        if ((stl == new_stl) != (scene == new_scene)) {
            ++seen_mismatch;
            // A pair from two runs is refused, never judged.
            const auto v = runTsf("verify " + (work / "m.stl").string() + " --scene " + (work / "m.stl.scene.json").string());
            EXPECT_EQ(v.exit_code, kExitBadInput) << v.output;
            EXPECT_NE(v.output.find("different runs of tsf gen"), std::string::npos) << v.output;
        }
    }
    std::fprintf(stderr, "%d kills: %d left the new model, %d a mismatched pair (refused), %d keys of another run (named)\n",
                 kKills, seen_new, seen_mismatch, seen_key_mismatch);
    // The next complete run removes what the killed ones left.
    timedRun(gen(work, "new.csv"));
    EXPECT_EQ(temporaryFiles(work), 0);
    EXPECT_EQ(readText(work / "m.stl"), new_stl);
    const auto v = runTsf("verify " + (work / "m.stl").string() + " --scene " + (work / "m.stl.scene.json").string());
    EXPECT_EQ(v.exit_code, kExitOk) << v.output;
}

// Starts tsf, sends it `sig` after `delay_s`, waits for it.
void signalAfter(const std::vector<std::string>& args, double delay_s, int sig) {
    const pid_t pid = startTsf(args);
    std::this_thread::sleep_for(std::chrono::duration<double>(delay_s));
    ::kill(pid, sig);
    while (::waitpid(-1, nullptr, 0) > 0) {
    }
}

// SIGTERM (what kill, a service manager or a closing session sends) at any
// moment while tsf gen replaces a model, its sidecar and its two keys: the
// four files are all the old ones or all the new ones, never a mix (the
// renames are made with the signal held off), and no temporary file stays.
TEST(KillSafety, GenTerminatedAnywhereLeavesTheOldSetOrTheNewOne) {
    Subreaper subreaper;
    const fs::path dir = scratchDir(), ref = dir / "reference", work = dir / "work";
    fs::create_directories(ref);
    fs::create_directories(work);
    writeText(dir / "old.csv", field(1));
    writeText(dir / "new.csv", field(2));
    const auto gen = [&](const fs::path& out_dir, const std::string& input) {
        return std::vector<std::string>{"gen", (dir / input).string(), "-o", (out_dir / "m.stl").string(),
                                        "--no-verify", "--cull", "none", "--title", "T"};
    };
    const char* names[] = {"m.stl", "m.stl.scene.json", "m.key.txt", "m.key.brf"};
    const auto read = [&](const fs::path& d) {
        std::vector<std::string> files;
        for (const char* n : names) files.push_back(readText(d / n));
        return files;
    };
    timedRun(gen(ref, "new.csv"));
    const std::vector<std::string> new_set = read(ref);
    const double full_s = timedRun(gen(work, "old.csv"));
    const std::vector<std::string> old_set = read(work);
    for (size_t k = 0; k < old_set.size(); ++k) ASSERT_NE(old_set[k], new_set[k]) << names[k];

    std::mt19937 rng(46);
    std::uniform_real_distribution<double> moment(0.3 * full_s, 1.1 * full_s);
    int seen_new = 0;
    for (int k = 0; k < kKills; ++k) {
        for (size_t f = 0; f < old_set.size(); ++f) writeText(work / names[f], old_set[f]);
        signalAfter(gen(work, "new.csv"), moment(rng), SIGTERM);
        const std::vector<std::string> now = read(work);
        ASSERT_TRUE(now == old_set || now == new_set)
            << "kill " << k << ": a mix (model " << (now[0] == new_set[0] ? "new" : "old") << ", sidecar "
            << (now[1] == new_set[1] ? "new" : "old") << ", key " << (now[2] == new_set[2] ? "new" : "old") << ", braille key "
            << (now[3] == new_set[3] ? "new" : "old") << ")";
        seen_new += now == new_set;
        EXPECT_EQ(temporaryFiles(work), 0) << "kill " << k;
    }
    std::fprintf(stderr, "%d SIGTERMs: %d left the new set, %d the old one\n", kKills, seen_new, kKills - seen_new);
    // What a SIGKILL between two renames can leave, made on purpose: each
    // key carries its model's stamp, and tsf verify names the key of the
    // other run; the same run writes the same keys.
    for (size_t f = 0; f < old_set.size(); ++f) writeText(work / names[f], new_set[f]);
    EXPECT_EQ(runTsf("verify " + (work / "m.stl").string()).exit_code, kExitOk);
    for (const char* key : {"m.key.txt", "m.key.brf"}) {
        writeText(work / key, old_set[std::string(key) == "m.key.txt" ? 2 : 3]);
        const auto v = runTsf("verify " + (work / "m.stl").string() + " --scene " + (work / "m.stl.scene.json").string());
        EXPECT_EQ(v.exit_code, kExitBadInput) << v.output;
        EXPECT_NE(v.output.find(std::string(key) + ": is the key of another version of m.stl"), std::string::npos) << v.output;
        writeText(work / key, new_set[std::string(key) == "m.key.txt" ? 2 : 3]);
    }
    EXPECT_NE(new_set[2].find("\nModel stamp: m.stl, "), std::string::npos) << "the stamp ends the key";
}

TEST(KillSafety, RenderKilledAnywhereLeavesTheOldFileOrTheNewOne) {
    Subreaper subreaper;
    const fs::path dir = scratchDir();
    writeText(dir / "old.csv", "1,2,3\n4,5,6\n");
    writeText(dir / "new.csv", "6,5,4\n3,2,1\n");
    ASSERT_EQ(runTsf("gen " + (dir / "old.csv").string() + " --scad " + (dir / "old.scad").string()).exit_code, kExitOk);
    ASSERT_EQ(runTsf("gen " + (dir / "new.csv").string() + " --scad " + (dir / "new.scad").string()).exit_code, kExitOk);
    const auto render = [&](const std::string& scad) {
        return std::vector<std::string>{"render", (dir / scad).string(), "-o", (dir / "r.stl").string()};
    };
    timedRun(render("new.scad"));
    const std::string new_stl = readText(dir / "r.stl");
    const double full_s = timedRun(render("old.scad"));
    const std::string old_stl = readText(dir / "r.stl");
    ASSERT_FALSE(old_stl.empty());
    ASSERT_NE(old_stl, new_stl);

    std::mt19937 rng(15);
    std::uniform_real_distribution<double> moment(0.0, 1.1 * full_s);
    for (int k = 0; k < 8; ++k) {
        writeText(dir / "r.stl", old_stl);
        killAfter(render("new.scad"), moment(rng));
        const std::string stl = readText(dir / "r.stl");
        ASSERT_TRUE(stl == old_stl || stl == new_stl) << "kill " << k << ": a model of " << stl.size() << " bytes";
    }
    timedRun(render("new.scad"));
    EXPECT_EQ(temporaryFiles(dir), 0);
    EXPECT_EQ(readText(dir / "r.stl"), new_stl);
}

}  // namespace
}  // namespace tsf
