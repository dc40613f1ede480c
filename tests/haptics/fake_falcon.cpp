#include "tests/haptics/fake_falcon.h"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "tests/haptics/fake_falcon_mechanism.h"

namespace tsf::haptics::testing {
namespace {

constexpr uint16_t kDivisorLoader = 0x4138, kDivisorUpload = 0x0015, kDivisorNormal = 0x0002;
/// Modem-status bytes as an FT232 sends them: bit 0 always set, CTS/DSR
/// (0x10, 0x20) as the DSP drives them; line status THRE/TEMT (0x20,
/// 0x40) as its transmitter empties, DR (0x01) when data waits. Cycled
/// through packet by packet.
constexpr uint8_t kModemStatus[] = {0x31, 0x01, 0x11, 0x21};
constexpr uint8_t kLineStatus[] = {0x60, 0x00, 0x61, 0x20, 0x40};
/// Encoder offset before homing (any number will do: the counts are relative).
constexpr int kUnhomedOffset = 1234;
constexpr double kPacketPeriod_s = 0.001;
/// Data bytes in one USB packet of the chip (64 less the two status bytes).
constexpr size_t kPacketData = kUsbPacketBytes - 2;
/// A split reply's second part comes this much after its first.
constexpr double kSplitGap_us = 1500.0;

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
    firmware_running_ = cfg_.firmware_running || cfg_.homed_at_start;
    homed_ = cfg_.homed_at_start;
    divisor_ = cfg_.divisor_at_start;
    latency_ms_ = cfg_.latency_at_start_ms;
    p_ = cfg_.pose ? cfg_.pose(0.0) : Vec3(0.0);
}

double FakeFalcon::byteTime_us() const {
    // 10 bits (start, 8 data, stop) at the line's speed.
    const double baud = divisor_ == kDivisorNormal ? 1.5e6 : divisor_ == kDivisorUpload ? 3e6 / 21.0 : 9600.0;
    return 10.0 / baud * 1e6;
}

void FakeFalcon::send(std::span<const uint8_t> bytes, double after_us) {
    double t = std::max(now_us_ + after_us, line_free_us_);
    for (uint8_t b : bytes) {
        t += byteTime_us();
        rx_.push_back({b, t});
    }
    line_free_us_ = t;
}

UsbResult FakeFalcon::control(uint8_t request, uint16_t value, uint16_t index, int) noexcept {
    if (unplugged_) return {UsbStatus::kNoDevice, 0};
    controls_.push_back({request, value, index});
    switch (request) {
    case 0:  // reset (0) or purge, named from the chip's side (libftdi 1.5's SIO_TCIFLUSH 2, SIO_TCOFLUSH 1)
        if (value == 2) {
            // What waits for the host, in the chip: bytes still on the DSP's
            // serial line arrive after the purge.
            while (!rx_.empty() && rx_.front().at_us <= now_us_) rx_.pop_front();
        }
        if (value == 1) in_.clear();
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
        if (is_c && ++handshakes_ > cfg_.handshake_after && !cfg_.silent_loader) {
            const uint8_t answer[] = {0x0A, 'D', ',', 0x0D};
            send(answer, double(data.size()) * byteTime_us() + cfg_.loader_turnaround_ms * 1000.0);
        }
        return;
    }
    if (loader_ == Loader::kAutobaud && divisor_ == kDivisorUpload) {
        if (data.size() == 1 && data[0] == 'A') {
            const uint8_t a = 'A';
            send({&a, 1}, byteTime_us() + cfg_.loader_turnaround_ms * 1000.0);
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
        // Each byte is echoed as it comes in: the echo starts one byte time
        // (plus the loader's turnaround) after the write.
        ++upload_writes_;
        double after_us = byteTime_us() + cfg_.loader_turnaround_ms * 1000.0;
        if (cfg_.slow_echo_every > 0 && upload_writes_ % cfg_.slow_echo_every == 0)
            after_us += cfg_.slow_echo_ms * 1000.0;
        if (!echo.empty()) send(echo, after_us);
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
    if (c.status & kFalconHoming) {
        ++homing_seen_;
    } else {
        // Without the homing bit the firmware drops its homing: the motors
        // must be homed again (libnifalcon sets the bit in every packet).
        homing_seen_ = 0;
        homed_ = false;
    }
    if (cfg_.homing_packets >= 0 && homing_seen_ >= cfg_.homing_packets) homed_ = true;
    // The motors push with the commanded torques at the current pose.
    const Vec3 force = fakeMotorForce(p_, c.motor);
    forces_.push_back(force);
    stepGrip(force);

    const long n = ++replies_;
    if (cfg_.silent_after_packets >= 0 && n > cfg_.silent_after_packets) silent_ = true;
    if (cfg_.on_command) cfg_.on_command();
    if (silent_ || (cfg_.drop_reply_every > 0 && n % cfg_.drop_reply_every == 0)) return;
    reply_positions_.push_back(p_);
    FalconReport rep;
    std::array<double, 3> now;
    if (fakeThighAngles(p_, now))
        for (size_t i = 0; i < 3; ++i) rep.encoder[i] = int16_t(fakeEncoderCount(now[i]) + (homed_ ? 0 : kUnhomedOffset));
    rep.buttons = cfg_.buttons ? cfg_.buttons(t_s_) : 0;
    rep.homed_mask = homed_ ? kFalconAllHomed : uint8_t(homing_seen_ > 0 ? 0x1 : 0x0);
    const FalconPacket frame = encodeFalconReport(rep);
    // The command's last byte came in one byte time after the write; the
    // firmware answers a turnaround later.
    const double after_us = double(kFalconPacketBytes) * byteTime_us() + cfg_.reply_turnaround_us;
    if (cfg_.garbage_every > 0 && n % cfg_.garbage_every == 0) {
        const uint8_t garbage[] = {'>', 0x41, '<', 0x13, '<', 0x42, 0x00};
        send(garbage, after_us);
    }
    if (cfg_.split_every > 0 && n % cfg_.split_every == 0) {
        send(std::span<const uint8_t>(frame.data(), 7), after_us);
        send(std::span<const uint8_t>(frame.data() + 7, frame.size() - 7), after_us + kSplitGap_us);
    } else {
        send(frame, after_us);
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

UsbResult FakeFalcon::bulkRead(std::span<uint8_t> buffer, int timeout_ms) noexcept {
    if (unplugged_) return {UsbStatus::kNoDevice, 0};
    if (buffer.size() < 2) return {UsbStatus::kError, 0};
    // libusb's timeout 0 waits for ever; the latency timer ends every wait.
    const double deadline = timeout_ms > 0 ? now_us_ + timeout_ms * 1000.0 : 1e300;
    double t = now_us_;
    size_t n = 0;
    for (;;) {
        // The chip sends a full packet once 62 bytes are in, else what it
        // has when the latency timer runs out (counted from its last packet).
        const size_t room = std::min(kUsbPacketBytes, buffer.size() - n) - 2;
        const double t_full = rx_.size() >= room ? std::max(t, rx_[room - 1].at_us) : 1e300;
        const double t_timer = std::max(t, last_packet_us_ + latency_ms_ * 1000.0);
        const double t_next = std::min(t_full, t_timer);
        if (t_next > deadline) {
            now_us_ = deadline;
            return {UsbStatus::kTimeout, n};
        }
        t = t_next;
        buffer[n] = kModemStatus[packets_to_host_ % std::size(kModemStatus)];
        buffer[n + 1] = kLineStatus[packets_to_host_ % std::size(kLineStatus)];
        ++packets_to_host_;
        size_t take = 0;
        while (take < room && take < rx_.size() && rx_[take].at_us <= t) {
            buffer[n + 2 + take] = rx_[take].byte;
            ++take;
        }
        rx_.erase(rx_.begin(), rx_.begin() + long(take));
        n += 2 + take;
        last_packet_us_ = t;
        // A short packet ends the transfer, and so does a full buffer.
        if (take < kPacketData || buffer.size() - n < 2) {
            now_us_ = t;
            return {UsbStatus::kOk, n};
        }
    }
}

}  // namespace tsf::haptics::testing
