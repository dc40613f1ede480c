#include "tests/haptics/fake_falcon.h"

#include <algorithm>
#include <cmath>

#include "haptics/falcon/falcon_kinematics.h"

namespace tsf::haptics::testing {
namespace {

constexpr uint16_t kDivisorLoader = 0x4138, kDivisorUpload = 0x0015, kDivisorNormal = 0x0002;
constexpr uint8_t kModemStatus = 0x31, kLineStatus = 0x60;  // what an idle FT232 reports
/// Encoder offset before homing (any number will do: the counts are relative).
constexpr int kUnhomedOffset = 1234;
constexpr double kPacketPeriod_s = 0.001;

}  // namespace

std::vector<uint8_t> fakeFirmwareImage(size_t n) {
    std::vector<uint8_t> img(n);
    for (size_t i = 0; i < n; ++i) img[i] = uint8_t((i * 37 + 11) & 0xFF);
    if (n >= 2) {
        img[0] = 0xAA;
        img[1] = 0x08;
    }
    return img;
}

FakeFalcon::FakeFalcon(FakeFalconConfig config) : cfg_(std::move(config)) {
    firmware_running_ = cfg_.firmware_running;
    p_ = cfg_.pose ? cfg_.pose(0.0) : Vec3(0.0);
}

void FakeFalcon::queue(std::vector<uint8_t> bytes) {
    out_.push_back({std::move(bytes), reads_ + reply_delay_reads});
}

UsbResult FakeFalcon::control(uint8_t request, uint16_t value, uint16_t index, int) noexcept {
    if (unplugged_) return {UsbStatus::kNoDevice, 0};
    controls_.push_back({request, value, index});
    switch (request) {
    case 0:  // purge
        if (value == 1) out_.clear();
        if (value == 2) in_.clear();
        break;
    case 1:  // modem control: DTR is bit 0 of the state, enabled by bit 8 of the mask
        if (value & 0x0100) {
            const bool high = value & 0x0001;
            if (high && !dtr_ && divisor_ == kDivisorLoader) {
                // DTR edge: the DSP resets into its boot loader.
                firmware_running_ = false;
                loader_ = Loader::kHandshake;
                homed_ = false;
                homing_seen_ = 0;
            }
            dtr_ = high;
        }
        break;
    case 3: {  // baud divisor
        const uint16_t before = divisor_;
        divisor_ = value;
        if (value == kDivisorUpload && loader_ == Loader::kHandshake && handshakes_ > cfg_.handshake_after &&
            !cfg_.silent_loader)
            loader_ = Loader::kAutobaud;
        if (value == kDivisorNormal && before != kDivisorNormal && loader_ == Loader::kUpload) {
            const bool complete = cfg_.firmware_bytes ? uploaded_ == cfg_.firmware_bytes : uploaded_ > 0;
            firmware_running_ = complete && !upload_damaged_;
            loader_ = Loader::kOff;
        }
        break;
    }
    case 9: latency_ms_ = value; break;
    default: break;
    }
    return {UsbStatus::kOk, 0};
}

void FakeFalcon::onLoaderBytes(std::span<const uint8_t> data) {
    if (loader_ == Loader::kHandshake && divisor_ == kDivisorLoader) {
        const bool is_c = data.size() == 3 && data[0] == 0x0A && data[1] == 'C' && data[2] == 0x0D;
        if (is_c && ++handshakes_ > cfg_.handshake_after && !cfg_.silent_loader)
            queue({0x0A, 'D', ',', 0x0D});
        return;
    }
    if (loader_ == Loader::kAutobaud && divisor_ == kDivisorUpload) {
        if (data.size() == 1 && data[0] == 'A') {
            queue({'A'});
            loader_ = Loader::kUpload;
            ++upload_attempts_;
            uploaded_ = 0;
            upload_damaged_ = false;
        }
        return;
    }
    if (loader_ == Loader::kUpload && divisor_ == kDivisorUpload) {
        std::vector<uint8_t> echo;
        for (uint8_t b : data) {
            const long at = long(uploaded_++);
            if (cfg_.swallow_echo_from >= 0 && at >= cfg_.swallow_echo_from) {
                upload_damaged_ = true;
                continue;
            }
            if (at == cfg_.corrupt_echo_byte && upload_attempts_ <= cfg_.corrupt_attempts) {
                b ^= 0x5A;  // the loader received (and echoes) a damaged byte
                upload_damaged_ = true;
            }
            echo.push_back(b);
        }
        if (!echo.empty()) queue(std::move(echo));
    }
}

void FakeFalcon::stepGrip(const Vec3& force_N) {
    t_s_ += kPacketPeriod_s;
    const Vec3 target = cfg_.pose ? cfg_.pose(t_s_) : p_;
    if (!cfg_.finger) {
        p_ = target;
        return;
    }
    // Semi-implicit Euler in 0.1 ms steps: mass, hand spring-damper, press.
    constexpr double kMass = 0.15, kHand = 300.0, kDamping = 4.0;
    for (int k = 0; k < 10; ++k) {
        const double dt = kPacketPeriod_s / 10;
        Vec3 f = force_N + kHand * (target - p_) - kDamping * v_;
        f.y += (cfg_.hand_y_N_per_m - kHand) * (target.y - p_.y) - cfg_.press_N;
        v_ += f * (dt / kMass);
        p_ += v_ * dt;
    }
}

void FakeFalcon::onCommand(const FalconCommand& c) {
    commands_.push_back(c);
    if (!homed_ && (c.motor[0] || c.motor[1] || c.motor[2])) ++nonzero_unhomed_;
    if (homed_) lowest_y_ = std::min(lowest_y_, p_.y);
    if (c.status & kFalconHoming) ++homing_seen_;
    if (cfg_.homing_packets >= 0 && homing_seen_ >= cfg_.homing_packets) homed_ = true;
    // The motors push with the commanded torques at the current pose.
    Vec3 force(0.0);
    FalconAngles theta;
    if (falconInverseKinematics(p_, theta)) force = falconForceFromCommands(p_, theta, c.motor);
    forces_.push_back(force);
    stepGrip(force);

    const long n = ++replies_;
    if (cfg_.silent_after_packets >= 0 && n > cfg_.silent_after_packets) silent_ = true;
    if (silent_ || (cfg_.drop_reply_every > 0 && n % cfg_.drop_reply_every == 0)) return;
    FalconReport rep;
    FalconAngles now;
    if (falconInverseKinematics(p_, now))
        for (size_t i = 0; i < 3; ++i)
            rep.encoder[i] = int16_t(std::lround(falconAngleToEncoder(now[i])) + (homed_ ? 0 : kUnhomedOffset));
    rep.buttons = cfg_.buttons ? cfg_.buttons(t_s_) : 0;
    rep.homed_mask = homed_ ? kFalconAllHomed : uint8_t(homing_seen_ > 0 ? 0x1 : 0x0);
    const FalconPacket frame = encodeFalconReport(rep);
    if (cfg_.garbage_every > 0 && n % cfg_.garbage_every == 0) queue({'>', 0x41, '<', 0x13, '<', 0x42, 0x00});
    if (cfg_.split_every > 0 && n % cfg_.split_every == 0) {
        queue(std::vector<uint8_t>(frame.begin(), frame.begin() + 7));
        out_.push_back({std::vector<uint8_t>(frame.begin() + 7, frame.end()), reads_ + reply_delay_reads + 1});
    } else {
        queue(std::vector<uint8_t>(frame.begin(), frame.end()));
    }
}

void FakeFalcon::onCommandBytes(std::span<const uint8_t> data) {
    in_.insert(in_.end(), data.begin(), data.end());
    while (in_.size() >= kFalconPacketBytes) {
        FalconCommand c;
        const std::span<const uint8_t, kFalconPacketBytes> frame(in_.data(), kFalconPacketBytes);
        if (decodeFalconCommand(frame, c)) {
            in_.erase(in_.begin(), in_.begin() + long(kFalconPacketBytes));
            if (cfg_.unplug_after_packets >= 0 && long(commands_.size()) >= cfg_.unplug_after_packets) {
                unplugged_ = true;
                return;
            }
            onCommand(c);
        } else {
            in_.erase(in_.begin());  // the firmware skips to the next frame start
        }
    }
}

UsbResult FakeFalcon::bulkWrite(std::span<const uint8_t> data, int) noexcept {
    if (unplugged_) return {UsbStatus::kNoDevice, 0};
    if (firmware_running_ && divisor_ == kDivisorNormal) onCommandBytes(data);
    else if (!firmware_running_) onLoaderBytes(data);
    return unplugged_ ? UsbResult{UsbStatus::kNoDevice, 0} : UsbResult{UsbStatus::kOk, data.size()};
}

UsbResult FakeFalcon::bulkRead(std::span<uint8_t> buffer, int) noexcept {
    if (unplugged_) return {UsbStatus::kNoDevice, 0};
    ++reads_;
    if (buffer.size() < 2) return {UsbStatus::kError, 0};
    // One packet: status bytes, then as much ready data as fits in 62 bytes.
    buffer[0] = kModemStatus;
    buffer[1] = kLineStatus;
    size_t n = 2;
    const size_t room = std::min(buffer.size(), kUsbPacketBytes);
    while (!out_.empty() && out_.front().ready_at_read <= reads_ && n < room) {
        Pending& p = out_.front();
        const size_t take = std::min(room - n, p.bytes.size());
        std::copy(p.bytes.begin(), p.bytes.begin() + long(take), buffer.begin() + long(n));
        n += take;
        p.bytes.erase(p.bytes.begin(), p.bytes.begin() + long(take));
        if (p.bytes.empty()) out_.pop_front();
    }
    return {UsbStatus::kOk, n};
}

}  // namespace tsf::haptics::testing
