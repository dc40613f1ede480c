// `tsf feel --device falcon` end to end without hardware: the real tsf
// binary, its libusb transport and the whole driver, with libusb replaced
// (LD_PRELOAD) by a stand-in that has a fake Falcon on its bus
// (fake_libusb/fake_libusb.cpp). Covers every message a user can get
// before a session and a complete session: firmware upload, homing, the
// loop, forces through the kinematics into a simulated finger, and zero
// force at the end.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "tests/haptics/fake_falcon.h"
#include "tests/haptics/fake_falcon_report.h"
#include "tests/support/run.h"

namespace fs = std::filesystem;

namespace {

const fs::path kScratch = fs::path(TSF_TEST_SCRATCH) / "feel-falcon";

fs::path scratchFile(const std::string& suffix) {
    fs::create_directories(kScratch);
    return kScratch / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" + suffix);
}

/// A firmware file the fake accepts.
std::string firmwareFile(size_t bytes = 7400) {
    const fs::path p = scratchFile("firmware.bin");
    const auto img = tsf::haptics::testing::fakeFirmwareImage(bytes);
    std::ofstream(p, std::ios::binary).write(reinterpret_cast<const char*>(img.data()), std::streamsize(img.size()));
    return p.string();
}

std::string volcano() { return std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv"; }

/// Runs tsf with the libusb stand-in and the given fake's environment.
tsf::test::RunResult runWithFakeFalcon(const std::string& env, const std::string& args) {
    return tsf::test::runCommand("env LD_PRELOAD=" + std::string(TSF_FAKE_LIBUSB) + " " + env + " " + TSF_BINARY +
                                 " " + args);
}

std::map<std::string, std::string> readReport(const fs::path& p) {
    return tsf::haptics::testing::readFakeFalconReport(p.string());
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(FeelFalconCli, EveryDeviceProblemSaysWhatToDo) {
    struct Case {
        const char* env;
        std::vector<const char*> says;
    };
    const Case cases[] = {
        {"TSF_FAKE_FALCON=absent", {"no Novint Falcon found", "lsusb -d 0403:cb48", "power supply"}},
        {"TSF_FAKE_FALCON=access", {"permission denied", "70-novint-falcon.rules", "udevadm control --reload-rules"}},
        {"TSF_FAKE_FALCON=busy", {"in use by another program"}},
        {"", {"no firmware running", "--firmware FILE"}},  // powered up, no file given
    };
    for (const Case& c : cases) {
        const auto r = runWithFakeFalcon(c.env, "feel " + volcano() + " --device falcon");
        EXPECT_EQ(r.exit_code, tsf::test::kExitDeviceFailed) << c.env << "\n" << r.output;
        for (const char* part : c.says) EXPECT_TRUE(has(r.output, part)) << c.env << ": " << part << "\n" << r.output;
    }
}

TEST(FeelFalconCli, BadFirmwareFileIsBadInputAndTheDeviceIsNotTouched) {
    const fs::path bad = scratchFile("notes.txt");
    std::ofstream(bad) << std::string(4000, 'x');
    const fs::path report = scratchFile("report.txt");
    fs::remove(report);
    const auto r = runWithFakeFalcon("TSF_FAKE_FALCON_REPORT=" + report.string(),
                                     "feel " + volcano() + " --device falcon --firmware " + bad.string());
    EXPECT_EQ(r.exit_code, tsf::test::kExitBadInput) << r.output;
    EXPECT_TRUE(has(r.output, "AA 08")) << r.output;
    EXPECT_FALSE(fs::exists(report));  // never opened
    const auto sim = tsf::test::runTsf("feel " + volcano() + " --firmware " + firmwareFile());
    EXPECT_EQ(sim.exit_code, tsf::test::kExitBadInput) << sim.output;  // --firmware without a Falcon
}

TEST(FeelFalconCli, ACompleteSessionLoadsFirmwareHomesRendersAndEndsAtZeroForce) {
    const std::string fw = firmwareFile(7400);
    const fs::path report = scratchFile("report.txt"), log = scratchFile("log.csv");
    const auto r = runWithFakeFalcon(
        "TSF_FAKE_FALCON_FIRMWARE_BYTES=7400 TSF_FAKE_FALCON_REPORT=" + report.string(),
        "feel " + volcano() + " --device falcon --firmware " + fw + " --duration 5 --no-realtime --json --log " +
            log.string());
    ASSERT_EQ(r.exit_code, tsf::test::kExitOk) << r.output;
    EXPECT_TRUE(has(r.output, "pull the grip all the way out")) << r.output;  // the homing instructions
    const auto j = nlohmann::json::parse(r.output.substr(r.output.find('{')));
    EXPECT_EQ(j["device"], "falcon");
    EXPECT_EQ(j["loop"]["end"], "duration");
    EXPECT_TRUE(j["loop"]["zero_force_sent"].get<bool>());
    const auto& f = j["falcon"];
    EXPECT_EQ(f["firmware"], "loaded");
    EXPECT_EQ(f["firmware_bytes"], 7400);
    EXPECT_EQ(f["firmware_attempts"], 1);
    const double ticks = j["loop"]["ticks"].get<double>();
    EXPECT_GT(f["frames_received"].get<double>(), 0.99 * ticks);  // one frame per tick
    EXPECT_EQ(f["solver_fallbacks"], 0);
    EXPECT_EQ(f["refused_forces"], 0);
    EXPECT_GT(f["homed_ticks"].get<double>(), 4000.0);
    EXPECT_LE(j["forces"]["max_N"].get<double>(), 6.0 + 1e-9);
    EXPECT_GT(j["forces"]["contact_ticks"].get<int>(), 1000);  // the finger came down onto the volcano
    EXPECT_GT(j["coverage"]["touched"].get<int>(), 0);

    // What the device saw.
    auto seen = readReport(report);
    EXPECT_EQ(seen["uploads"], "1");
    EXPECT_EQ(seen["firmware_bytes"], "7400");
    EXPECT_EQ(seen["latency_ms"], "1");
    EXPECT_EQ(seen["nonzero_before_homed"], "0");  // no force before homing
    EXPECT_EQ(seen["last_command_zero"], "1");     // zero force at the end
    EXPECT_EQ(seen["homed"], "1");
    EXPECT_LE(std::stod(seen["max_force_N"]), 6.05);  // as felt by the motors, rounding included

    // Through kinematics, motors and back: the surface holds the pressing
    // finger up (forces point up while touching) and it never sinks deep.
    std::ifstream in(log);
    std::string line;
    std::getline(in, line);
    int contact = 0, upward = 0;
    while (std::getline(in, line)) {
        std::vector<std::string> c;
        size_t at = 0;
        for (size_t next; (next = line.find(',', at)) != std::string::npos; at = next + 1) c.push_back(line.substr(at, next - at));
        c.push_back(line.substr(at));
        if (c[11] != "1") continue;
        ++contact;
        if (std::stod(c[5]) > 0.0) ++upward;
    }
    EXPECT_GT(contact, 1000);
    EXPECT_GT(upward, 0.95 * contact);
    EXPECT_GT(std::stod(seen["lowest_homed_y_m"]), -0.024 - 0.006);  // the floor, with the entry depth to spare
}

TEST(FeelFalconCli, FirmwareAlreadyRunningNeedsNoFile) {
    const auto r = runWithFakeFalcon("TSF_FAKE_FALCON_RUNNING=1",
                                     "feel " + volcano() + " --device falcon --duration 1 --no-realtime");
    ASSERT_EQ(r.exit_code, tsf::test::kExitOk) << r.output;
    EXPECT_TRUE(has(r.output, "firmware already running")) << r.output;
    EXPECT_TRUE(has(r.output, "zero force sent")) << r.output;
}

TEST(FeelFalconCli, RealTimeSessionReportsTheAchievedRate) {
    const auto r = runWithFakeFalcon("TSF_FAKE_FALCON_RUNNING=1", "feel " + volcano() + " --device falcon --duration 1");
    ASSERT_EQ(r.exit_code, tsf::test::kExitOk) << r.output;
    EXPECT_TRUE(has(r.output, "real time")) << r.output;
    EXPECT_TRUE(has(r.output, "overruns")) << r.output;
    EXPECT_TRUE(has(r.output, "frames (")) << r.output;
}

TEST(FeelFalconCli, UnpluggedMidSessionExitsFour) {
    const auto r = runWithFakeFalcon("TSF_FAKE_FALCON_RUNNING=1 TSF_FAKE_FALCON_UNPLUG_AFTER=1500",
                                     "feel " + volcano() + " --device falcon --duration 5 --no-realtime");
    EXPECT_EQ(r.exit_code, tsf::test::kExitDeviceFailed) << r.output;
    EXPECT_TRUE(has(r.output, "unplugged or lost power")) << r.output;
}

TEST(FeelFalconCli, AFalconThatFallsSilentMidContactIsLeftAtZeroForceAndExitsFour) {
    // The finger is on the volcano from 1.5 s; at 3 s the firmware hangs:
    // it still takes commands, but no frame comes back.
    const fs::path report = scratchFile("report.txt");
    const auto r = runWithFakeFalcon(
        "TSF_FAKE_FALCON_RUNNING=1 TSF_FAKE_FALCON_SILENT_AFTER=3000 TSF_FAKE_FALCON_REPORT=" + report.string(),
        "feel " + volcano() + " --device falcon --duration 6 --no-realtime");
    EXPECT_EQ(r.exit_code, tsf::test::kExitDeviceFailed) << r.output;
    EXPECT_TRUE(has(r.output, "stopped answering")) << r.output;
    auto seen = readReport(report);
    EXPECT_GT(std::stod(seen["max_force_N"]), 0.5) << "the finger was pushed before the silence";
    EXPECT_EQ(seen["last_command_zero"], "1");  // the last command the device holds is zero
}
