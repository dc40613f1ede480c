// Every way a user ends `tsf feel --device falcon` leaves the Falcon at zero
// force: the real tsf binary on the fake Falcon (fake_libusb/), a signal
// sent while the simulated finger rests on the volcano under force, and the
// command the device holds afterwards read from the fake's report, which
// the fake keeps current on every command (so a killed process leaves it).
//   SIGINT, SIGTERM, SIGHUP, SIGQUIT: ramp out, zero, close, exit by the signal;
//   timeout's expiry: SIGTERM to the whole process group;
//   SIGTSTP: zero held while stopped, forces back after SIGCONT;
//   SIGKILL: nothing in the process runs; its guardian zeroes the device.
#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/haptics/fake_falcon_report.h"

namespace fs = std::filesystem;

namespace {

const fs::path kScratch = fs::path(TSF_TEST_SCRATCH) / "feel-falcon-signals";

fs::path scratchFile(const std::string& suffix) {
    fs::create_directories(kScratch);
    return kScratch / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" + suffix);
}

std::map<std::string, std::string> readReport(const fs::path& p) {
    return tsf::haptics::testing::readFakeFalconReport(p.string());
}

/// A feel session on the fake Falcon (firmware running), until a signal
/// ends it; stdout and stderr go to files.
struct Session {
    fs::path report, out, err;
    pid_t pid = -1;       ///< the process signalled (tsf, or timeout around it)
    bool through_timeout = false;
    bool reaped = false;
    Session() = default;
    Session(Session&& o) noexcept
        : report(o.report), out(o.out), err(o.err), pid(o.pid), through_timeout(o.through_timeout), reaped(o.reaped) {
        o.reaped = true;
    }
    /// A test that failed before its signal leaves no session running.
    ~Session() {
        if (reaped || pid <= 0) return;
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
    }
};

Session start(const std::string& name, bool through_timeout = false) {
    Session s;
    s.report = scratchFile(name + "-report.txt");
    s.out = scratchFile(name + "-out.txt");
    s.err = scratchFile(name + "-err.txt");
    s.through_timeout = through_timeout;
    fs::remove(s.report);  // the report is the device's memory: start from a fresh device
    const std::string volcano = std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv";
    s.pid = fork();
    if (s.pid == 0) {
        setenv("LD_PRELOAD", TSF_FAKE_LIBUSB, 1);
        setenv("TSF_FAKE_FALCON_RUNNING", "1", 1);
        setenv("TSF_FAKE_FALCON_REPORT", s.report.c_str(), 1);
        const int out = open(s.out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        const int err = open(s.err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        dup2(out, 1);
        dup2(err, 2);
        // No end but the signal (virtual time: the loop runs as fast as it can).
        std::vector<const char*> argv;
        if (through_timeout) argv = {"timeout", "600"};
        for (const char* a : {TSF_BINARY, "feel", volcano.c_str(), "--device", "falcon", "--no-realtime", "--json"})
            argv.push_back(a);
        argv.push_back(nullptr);
        execvp(argv[0], const_cast<char* const*>(argv.data()));
        _exit(127);
    }
    return s;
}

/// Waits (at most 30 s, polling) until the device is homed, the finger
/// has been on the volcano for a while and the last command is a force.
bool waitForForce(const Session& s) {
    for (int k = 0; k < 1500; ++k) {
        auto r = readReport(s.report);
        if (r["homed"] == "1" && std::atol(r["commands"].c_str()) > 2500 && r["last_command_zero"] == "0" &&
            std::stod(r.count("max_force_N") ? r["max_force_N"] : "0") > 0.5)
            return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return false;
}

/// Waits for the process; its wait status.
int finish(Session& s) {
    int status = 0;
    while (waitpid(s.pid, &status, 0) < 0 && errno == EINTR) {
    }
    s.reaped = true;
    return status;
}

/// What the device holds, once the report's writer closed it (at most ten
/// seconds: a guardian may still be at work).
std::map<std::string, std::string> heldAfter(const Session& s) {
    std::map<std::string, std::string> r;
    for (int k = 0; k < 500; ++k) {
        r = readReport(s.report);
        if (r["open"] == "0") break;
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    return r;
}

std::string text(const fs::path& p) {
    std::ifstream f(p);
    return std::string(std::istreambuf_iterator<char>(f), {});
}

void expectZeroHeld(const Session& s, const std::map<std::string, std::string>& held) {
    EXPECT_EQ(held.at("open"), "0") << text(s.err);
    EXPECT_EQ(held.at("last_command_zero"), "1") << "the device holds " << held.at("last_command") << "\n" << text(s.err);
    EXPECT_EQ(held.at("homed"), "1");  // the homing bit was in every packet to the end
}

/// A stopping signal: the process ramps out, zeroes and closes the device,
/// reports, and ends as the signal asks.
void stoppingSignal(int sig, const std::string& name) {
    Session s = start(name);
    ASSERT_TRUE(waitForForce(s)) << text(s.err);
    kill(s.pid, sig);
    const int status = finish(s);
    if (sig == SIGINT || sig == SIGQUIT) {
        ASSERT_TRUE(WIFEXITED(status)) << name << " " << status;
        EXPECT_EQ(WEXITSTATUS(status), 128 + sig) << name;
    } else {
        ASSERT_TRUE(WIFSIGNALED(status)) << name << " " << status;
        EXPECT_EQ(WTERMSIG(status), sig) << name;
    }
    const auto held = heldAfter(s);
    expectZeroHeld(s, held);
    EXPECT_EQ(held.at("opens"), "1") << "no guardian had to act";
    // The summary was written after the device was closed, ramp and all.
    const std::string out = text(s.out);
    const auto j = nlohmann::json::parse(out.substr(out.find('{')));
    EXPECT_EQ(j["loop"]["end"], "interrupted");
    EXPECT_TRUE(j["loop"]["zero_force_sent"].get<bool>());
}

}  // namespace

TEST(FeelFalconSignals, CtrlCLeavesZero) { stoppingSignal(SIGINT, "int"); }
TEST(FeelFalconSignals, SigtermLeavesZero) { stoppingSignal(SIGTERM, "term"); }
TEST(FeelFalconSignals, ClosingTheTerminalLeavesZero) { stoppingSignal(SIGHUP, "hup"); }
TEST(FeelFalconSignals, CtrlBackslashLeavesZero) { stoppingSignal(SIGQUIT, "quit"); }

TEST(FeelFalconSignals, TimeoutsExpiryLeavesZero) {
    // timeout(1) on expiry (SIGALRM) sends SIGTERM to tsf and to its whole
    // process group, and exits 124.
    Session s = start("timeout", true);
    ASSERT_TRUE(waitForForce(s)) << text(s.err);
    kill(s.pid, SIGALRM);
    const int status = finish(s);
    ASSERT_TRUE(WIFEXITED(status)) << status;
    EXPECT_EQ(WEXITSTATUS(status), 124);
    const auto held = heldAfter(s);
    expectZeroHeld(s, held);
    EXPECT_EQ(held.at("opens"), "1") << "tsf itself zeroed the device; the guardian let it be";
}

TEST(FeelFalconSignals, CtrlZHoldsZeroWhileStoppedAndForcesComeBackAfterwards) {
    Session s = start("tstp");
    ASSERT_TRUE(waitForForce(s)) << text(s.err);
    kill(s.pid, SIGTSTP);
    int status = 0;
    ASSERT_EQ(waitpid(s.pid, &status, WUNTRACED), s.pid);
    ASSERT_TRUE(WIFSTOPPED(status)) << status;
    // Stopped: the device holds zero, still open, still homed.
    const auto stopped = readReport(s.report);
    EXPECT_EQ(stopped.at("open"), "1");
    EXPECT_EQ(stopped.at("last_command_zero"), "1") << "the device holds " << stopped.at("last_command");
    EXPECT_EQ(stopped.at("homed"), "1");
    const long commands = std::atol(stopped.at("commands").c_str());
    // Continued: the session goes on and forces come back (ramped in again:
    // the loop's own tests check the ramp).
    kill(s.pid, SIGCONT);
    bool forces_again = false;
    for (int k = 0; k < 3000 && !forces_again; ++k) {
        auto r = readReport(s.report);
        forces_again = std::atol(r["commands"].c_str()) > commands + 1500 && r["last_command_zero"] == "0";
        if (!forces_again) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_TRUE(forces_again) << text(s.err);
    kill(s.pid, SIGINT);
    status = finish(s);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    expectZeroHeld(s, heldAfter(s));
    const std::string out = text(s.out);
    const auto j = nlohmann::json::parse(out.substr(out.find('{')));
    EXPECT_EQ(j["loop"]["pauses"], 1);
}

TEST(FeelFalconSignals, SigkillIsCoveredByTheGuardian) {
    Session s = start("kill");
    ASSERT_TRUE(waitForForce(s)) << text(s.err);
    const auto before = readReport(s.report);
    EXPECT_EQ(before.at("last_command_zero"), "0");
    kill(s.pid, SIGKILL);
    const int status = finish(s);
    ASSERT_TRUE(WIFSIGNALED(status));
    EXPECT_EQ(WTERMSIG(status), SIGKILL);
    // The killed process left the device open and pushing; the guardian
    // opened it again (a second open) and left it at zero.
    const auto held = heldAfter(s);
    expectZeroHeld(s, held);
    EXPECT_EQ(held.at("opens"), "2");
    EXPECT_NE(held.at("pid"), std::to_string(s.pid));
    bool said = false;  // the guardian says so once it has closed the device
    for (int k = 0; k < 250 && !said; ++k) {
        said = text(s.err).find("its guardian set it to zero force") != std::string::npos;
        if (!said) std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    EXPECT_TRUE(said) << text(s.err);
}
