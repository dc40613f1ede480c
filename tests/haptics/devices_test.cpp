// Devices without hardware: the replay file reader (errors located), replay
// playback, the simulated finger and its scripts, and the velocity filter.
#include <cmath>
#include <fstream>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gen/util/error.h"
#include "haptics/field_mapping.h"
#include "haptics/replay_device.h"
#include "haptics/sim_device.h"
#include "haptics/velocity_filter.h"

using namespace tsf::haptics;

namespace {

/// Runs f and returns the InputError it throws (fails the test if none).
template <class F>
tsf::InputError inputErrorOf(F f) {
    try {
        f();
    } catch (const tsf::InputError& e) {
        return e;
    }
    ADD_FAILURE() << "expected an InputError";
    return tsf::InputError("none");
}

}  // namespace

TEST(Replay, ReadsTheLogFormatByColumnNames) {
    const auto s = parseReplayCsv(
        "t_s,x_m,y_m,z_m,fx_N,buttons\n"
        "# a comment\n"
        "0.0,0.001,0.002,0.003,9,0\n"
        "\n"
        "0.5,0.011,-0.002,0.0,9,4\r\n",
        "rec.csv");
    ASSERT_EQ(s.size(), 2u);
    EXPECT_DOUBLE_EQ(s[1].t_s, 0.5);
    EXPECT_EQ(s[1].position_m, Vec3(0.011, -0.002, 0.0));
    EXPECT_EQ(s[1].buttons, 4u);
}

TEST(Replay, BadFilesNameLineAndColumn) {
    auto e = inputErrorOf([] { parseReplayCsv("t_s,x_m,y_m\n0,0,0\n", "a.csv"); });
    EXPECT_EQ(e.line(), 1);
    EXPECT_NE(std::string(e.what()).find("z_m"), std::string::npos);
    e = inputErrorOf([] { parseReplayCsv("t_s,x_m,y_m,z_m\n0,0,0,0\n0.1,0,abc,0\n", "b.csv"); });
    EXPECT_EQ(e.line(), 3);
    EXPECT_EQ(e.column(), 7);
    e = inputErrorOf([] { parseReplayCsv("t_s,x_m,y_m,z_m\n0.2,0,0,0\n0.1,0,0,0\n", "c.csv"); });
    EXPECT_EQ(e.line(), 3);
    EXPECT_NE(std::string(e.what()).find("does not increase"), std::string::npos);
    e = inputErrorOf([] { parseReplayCsv("t_s,x_m,y_m,z_m\n0,0,25.0,0\n", "d.csv"); });
    EXPECT_NE(std::string(e.what()).find("metres"), std::string::npos);  // millimetres by mistake
    e = inputErrorOf([] { parseReplayCsv("t_s,x_m,y_m,z_m\n0,0,nan,0\n", "e.csv"); });
    EXPECT_EQ(e.line(), 2);
    inputErrorOf([] { parseReplayCsv("", "f.csv"); });
    inputErrorOf([] { parseReplayCsv("t_s,x_m,y_m,z_m\n", "g.csv"); });
    inputErrorOf([] { readReplayFile("/nonexistent/replay.csv"); });
    // An endless stream is refused before it is read (it used to fill memory).
    e = inputErrorOf([] { readReplayFile("/dev/zero"); });
    EXPECT_NE(std::string(e.what()).find("is a device, not a file"), std::string::npos) << e.what();
}

TEST(Replay, InterpolatesInTimeAndEndsAfterTheLastSample) {
    ReplayDevice d({{10.0, Vec3(0.0), 0}, {10.2, Vec3(0.02, 0.0, -0.01), 8}}, "r");
    DeviceState s;
    ASSERT_EQ(d.read(0.05, s), ReadStatus::kOk);
    EXPECT_NEAR(s.position_m.x, 0.005, 1e-12);
    EXPECT_NEAR(s.position_m.z, -0.0025, 1e-12);
    EXPECT_EQ(s.buttons, 0u);
    ASSERT_EQ(d.read(0.2, s), ReadStatus::kOk);
    EXPECT_EQ(s.buttons, 8u);
    EXPECT_EQ(d.read(0.21, s), ReadStatus::kEnded);
}

TEST(Sim, ScriptsStayInsideTheWorkspaceAndStartLifted) {
    const DeviceLimits limits;
    const FieldMapping m = mapFieldToWorkspace(30, 20, limits.workspace);
    for (SimTrajectory t : {SimTrajectory::kSweep, SimTrajectory::kTaps, SimTrajectory::kFinger}) {
        const SimScript s = makeSimScript(t, m);
        ASSERT_GE(s.keys.size(), 2u);
        EXPECT_GT(s.duration_s(), 5.0);
        EXPECT_GT(s.start_m.y, m.volume_top_y_m);  // above everything while forces ramp in
        for (const SimKeyframe& k : s.keys) {
            EXPECT_GE(k.x_m, m.west_x_m);
            EXPECT_LE(k.x_m, m.eastX());
            EXPECT_GE(k.z_m, m.northZ());
            EXPECT_LE(k.z_m, m.south_z_m);
            EXPECT_LT(k.lift_y_m, limits.workspace.max_m.y);
        }
    }
    EXPECT_THROW(parseSimTrajectory("zigzag"), tsf::InputError);
}

TEST(Sim, FingerFollowsTheHandAndAForceMovesIt) {
    SimScript s;
    s.name = "hold";
    s.keys = {{0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0}, {10.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0}};
    SimDevice d(s);
    DeviceState st;
    ASSERT_EQ(d.read(1.0, st), ReadStatus::kOk);
    EXPECT_LT(glm::length(st.position_m), 1e-9);  // held at the origin
    // A constant 3 N to the right against the 300 N/m hand settles at 1 cm.
    EXPECT_TRUE(d.writeForce(Vec3(3.0, 0.0, 0.0)));
    ASSERT_EQ(d.read(4.0, st), ReadStatus::kOk);
    EXPECT_NEAR(st.position_m.x, 3.0 / 300.0, 1e-5);
    EXPECT_GT(d.deviceWork_J(), 0.0);  // that force did work on the finger
    EXPECT_FALSE(d.writeForce(Vec3(100.0, 0.0, 0.0)));  // above the device limit: refused
    EXPECT_FALSE(d.writeForce(Vec3(std::nan(""), 0.0, 0.0)));
    EXPECT_EQ(d.read(10.5, st), ReadStatus::kEnded);
}

TEST(VelocityFilter, DifferencesOverTheWindowAndIgnoresBadSamples) {
    VelocityFilter f(0.010);
    EXPECT_EQ(f.update(0.0, Vec3(0.0)), Vec3(0.0));
    Vec3 v(0.0);
    for (int k = 1; k <= 50; ++k) v = f.update(k * 0.001, Vec3(0.02 * k * 0.001, 0.0, 0.0));
    EXPECT_NEAR(v.x, 0.02, 1e-12);
    // Encoder-like noise of +-38 um on a still probe: the window divides it.
    VelocityFilter g(0.010);
    double worst = 0.0;
    for (int k = 0; k < 200; ++k) {
        const Vec3 vn = g.update(k * 0.001, Vec3((k % 2 ? 38e-6 : -38e-6), 0.0, 0.0));
        if (k > 20) worst = std::max(worst, std::abs(vn.x));
    }
    EXPECT_LT(worst, 2 * 38e-6 / 0.010 + 1e-12);  // <= 7.6 mm/s instead of 76 mm/s raw
    EXPECT_EQ(g.update(std::nan(""), Vec3(0.0)), Vec3(0.0));
    EXPECT_EQ(g.update(1.0, Vec3(INFINITY, 0, 0)), Vec3(0.0));
    EXPECT_EQ(g.update(0.0, Vec3(0.0)), Vec3(0.0));  // time going backwards
}
