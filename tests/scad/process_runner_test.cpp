// runProcess: exit codes, captured output, time limits that stop the whole
// process group, progress callbacks, programs that do not exist.
#include <gtest/gtest.h>

#include <signal.h>

#include <chrono>
#include <unistd.h>

#include "runners/process_runner.h"

namespace tsf {
namespace {

TEST(ProcessRunner, CapturesOutputInOrderAndTheExitCode) {
    std::vector<std::string> lines;
    ProcessOptions o;
    o.on_line = [&](const std::string& line) { lines.push_back(line); };
    const ProcessResult r = runProcess({"sh", "-c", "echo one; echo two >&2; echo three; exit 3"}, o);
    EXPECT_EQ(r.end, ProcessResult::End::Exited);
    EXPECT_EQ(r.exit_code, 3);
    EXPECT_FALSE(r.succeeded());
    EXPECT_EQ(r.output, "one\ntwo\nthree\n");
    EXPECT_EQ(lines, (std::vector<std::string>{"one", "two", "three"}));
}

TEST(ProcessRunner, ArgumentsAreNotInterpretedByAShell) {
    const ProcessResult r = runProcess({"printf", "%s|", "a b", "$HOME", "*"}, {});
    EXPECT_TRUE(r.succeeded());
    EXPECT_EQ(r.output, "a b|$HOME|*|");
}

TEST(ProcessRunner, AProgramThatDoesNotExistIsNotStarted) {
    const ProcessResult r = runProcess({"tsf-no-such-program-xyz"}, {});
    EXPECT_EQ(r.end, ProcessResult::End::NotStarted);
    EXPECT_NE(r.start_error.find("tsf-no-such-program-xyz"), std::string::npos);
    EXPECT_EQ(runProcess({}, {}).end, ProcessResult::End::NotStarted);
    EXPECT_EQ(findExecutable("tsf-no-such-program-xyz"), "");
    EXPECT_NE(findExecutable("sh"), "");
}

// The time limit stops the child and what it started (a background sleep
// that holds the output pipe open would otherwise keep us waiting).
TEST(ProcessRunner, TimeLimitStopsTheWholeProcessGroup) {
    ProcessOptions o;
    o.timeout_s = 0.5;
    const auto t0 = std::chrono::steady_clock::now();
    const ProcessResult r = runProcess({"sh", "-c", "echo started; sleep 30 & sleep 30"}, o);
    const double waited = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    EXPECT_EQ(r.end, ProcessResult::End::TimedOut);
    EXPECT_LT(waited, 0.5 + kTerminateGraceS + 2.0);
    EXPECT_GE(r.elapsed_s, 0.5);
    EXPECT_EQ(r.output, "started\n");
}

TEST(ProcessRunner, ProgressIsReportedWhileItRuns) {
    std::vector<double> ticks;
    std::string last;
    ProcessOptions o;
    o.progress_interval_s = 0.2;
    o.on_progress = [&](double elapsed_s, const std::string& line) {
        ticks.push_back(elapsed_s);
        last = line;
    };
    const ProcessResult r = runProcess({"sh", "-c", "echo working; sleep 1"}, o);
    EXPECT_TRUE(r.succeeded());
    EXPECT_GE(ticks.size(), 3u);
    for (size_t i = 1; i < ticks.size(); ++i) EXPECT_GT(ticks[i], ticks[i - 1]);
    EXPECT_EQ(last, "working");
}

// Ctrl-C while a child runs stops the child (in its own process group, it
// does not get the terminal's SIGINT itself) and says so.
TEST(ProcessRunner, SigintStopsTheChild) {
    ProcessOptions o;
    // As soon as the child is running (it said so), this process gets SIGINT.
    o.on_line = [](const std::string& line) {
        if (line == "ready") kill(getpid(), SIGINT);
    };
    const ProcessResult r = runProcess({"sh", "-c", "echo ready; sleep 30"}, o);
    EXPECT_EQ(r.end, ProcessResult::End::Interrupted);
    EXPECT_LT(r.elapsed_s, 5.0);
}

TEST(ProcessRunner, KeepsOnlyTheFirstBytesOfHugeOutput) {
    ProcessOptions o;
    o.max_output_bytes = 1000;
    const ProcessResult r = runProcess({"sh", "-c", "yes hello | head -n 10000"}, o);
    EXPECT_TRUE(r.succeeded());
    EXPECT_EQ(r.output.size(), 1000u);
    EXPECT_EQ(r.output.size() + r.output_dropped_bytes, 60000u);
}

}  // namespace
}  // namespace tsf
