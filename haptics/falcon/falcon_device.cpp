#include "haptics/falcon/falcon_device.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>

namespace tsf::haptics {
namespace {

constexpr int kWriteTimeout_ms = 2;
constexpr int kCloseReadTimeout_ms = 5;
/// Draining the link: it is quiet after this many reads in a row without
/// data (each ends at the chip's 1 ms latency timer), and given up on
/// after kDrainMaxReads.
constexpr int kDrainQuietReads = 3;
constexpr int kDrainMaxReads = 50;

/// Reads until the device has sent everything it was going to (replies to
/// packets still in flight), then empties the chip's receive buffer: a
/// session must not start with another exchange's reply taken for its
/// first, or every later frame would answer the packet before (two in
/// flight, positions a packet old).
void drain(FtdiLink& link, std::span<uint8_t, FtdiLink::kDataBytes> buf) noexcept {
    for (int quiet = 0, k = 0; quiet < kDrainQuietReads && k < kDrainMaxReads; ++k) {
        const UsbResult r = link.read(buf, kCloseReadTimeout_ms);
        if (r.status == UsbStatus::kNoDevice) return;
        quiet = r.bytes == 0 ? quiet + 1 : 0;
    }
    link.purgeReceive();
}

}  // namespace

FalconDevice::FalconDevice(UsbOpener opener, FalconOptions options)
    : opener_(std::move(opener)), options_(std::move(options)) {}

FalconDevice::~FalconDevice() { close(); }

void FalconDevice::open() {
    close();
    failed_ = false;
    unplugged_ = false;
    silent_ = 0;
    failure_ = nullptr;
    stats_ = {};
    transport_ = opener_();
    link_ = std::make_unique<FtdiLink>(*transport_);
    const std::string where = std::string(" (") + transport_->location() + ")";
    if (!setFalconNormalMode(*link_)) {
        close();
        throw DeviceError("the Falcon's USB serial chip did not accept its settings" + where +
                          "; unplug the Falcon, plug it back in and try again");
    }
    if (falconFirmwareRunning(*link_, options_.firmware_check_tries)) {
        stats_.firmware_was_running = true;
    } else if (options_.firmware.empty()) {
        close();
        throw DeviceError("the Falcon" + where +
                          " has no firmware running (it forgets it whenever its power supply is off). "
                          "Give the firmware file with --firmware FILE (nvent_firmware.bin from Novint's "
                          "Falcon SDK; tsf cannot ship it); see docs/haptics.md");
    } else {
        try {
            stats_.firmware = loadFalconFirmware(*link_, options_.firmware, options_.firmware_load);
        } catch (...) {
            close();
            throw;
        }
        if (!falconFirmwareRunning(*link_, options_.firmware_check_tries)) {
            close();
            throw DeviceError("the firmware was uploaded and every chunk echoed correctly, but the Falcon" + where +
                              " does not answer; switch its power off and on and try again");
        }
    }
    // The check above may have left replies in flight; start clean and learn
    // the homed state from one exchange.
    drain(*link_, buf_);
    parser_.clear();
    awaiting_ = false;
    if (!send(FalconCommand{{0, 0, 0}, statusBits()})) {
        close();
        throw DeviceError("the Falcon" + where + " stopped answering right after it was opened");
    }
    for (int k = 0; k < options_.firmware_check_tries && awaiting_; ++k) {
        const UsbResult r = link_->read(buf_, kCloseReadTimeout_ms);
        parser_.push(std::span<const uint8_t>(buf_.data(), r.bytes));
        FalconReport rep;
        while (parser_.next(rep)) {
            takeFrame(rep);
            awaiting_ = false;
        }
    }
    awaiting_ = false;
    stats_.packets_sent = stats_.frames_received = 0;
    stats_.ticks_homed = 0;
}

void FalconDevice::close() noexcept {
    if (link_ && !unplugged_) {
        // Zero force, acknowledged when the device still answers. A device
        // that stopped answering may still be listening (a hung reply path,
        // a stalled host buffer): it is told too, without waiting for it.
        const FalconCommand zero{{0, 0, 0}, kFalconHoming};
        for (int k = 0; k < options_.close_packets; ++k) {
            const FalconPacket p = encodeFalconCommand(zero);
            const UsbResult w = link_->write(p, kWriteTimeout_ms);
            if (w.status == UsbStatus::kNoDevice) break;
            sent_ = zero;
            if (failed_) continue;
            const UsbResult r = link_->read(buf_, kCloseReadTimeout_ms);
            if (r.status == UsbStatus::kNoDevice) break;
        }
    }
    link_.reset();
    transport_.reset();
    awaiting_ = false;
}

void FalconDevice::holdZero() noexcept {
    if (!link_ || unplugged_) return;
    // Zero packets, each answered when the device still answers; the
    // replies keep the position current, and none is left in flight.
    const FalconCommand zero{{0, 0, 0}, statusBits()};
    for (int k = 0; k < options_.close_packets; ++k) {
        if (!send(zero)) return;
        if (failed_) continue;
        const UsbResult r = link_->read(buf_, kCloseReadTimeout_ms);
        if (r.status == UsbStatus::kNoDevice) {
            unplugged_ = true;
            fail("the Falcon was unplugged or lost power during the session");
            return;
        }
        parser_.push(std::span<const uint8_t>(buf_.data(), r.bytes));
        FalconReport rep;
        while (parser_.next(rep)) takeFrame(rep);
    }
    awaiting_ = false;
    silent_ = 0;
}

void FalconDevice::fail(const char* why) noexcept {
    if (!failed_) failure_ = why;
    failed_ = true;
}

uint8_t FalconDevice::statusBits() const noexcept {
    uint8_t s = kFalconHoming;
    if (!homed_) s |= kFalconLedRed;
    else if (volume_) s |= kFalconLedGreen | kFalconLedBlue;
    else if (contact_) s |= kFalconLedBlue;
    else s |= kFalconLedGreen;
    return s;
}

void FalconDevice::showStatus(bool in_contact, bool volume_mode) noexcept {
    contact_ = in_contact;
    volume_ = volume_mode;
}

bool FalconDevice::send(const FalconCommand& command) noexcept {
    const FalconPacket p = encodeFalconCommand(command);
    const UsbResult w = link_->write(p, kWriteTimeout_ms);
    if (w.status == UsbStatus::kNoDevice) {
        unplugged_ = true;
        fail("the Falcon was unplugged or lost power during the session");
        return false;
    }
    if (!w.ok()) {
        ++stats_.usb_errors;
        return false;
    }
    sent_ = command;
    awaiting_ = true;
    since_sent_ = 0;
    ++stats_.packets_sent;
    return true;
}

void FalconDevice::takeFrame(const FalconReport& rep) noexcept {
    report_ = rep;
    if (rep.unknown_bits) ++stats_.frames_with_unknown_bits;
    ++stats_.frames_received;
    homed_ = rep.homed();
    if (!homed_) {
        pose_ok_ = false;  // counts are relative to wherever the power came on
        return;
    }
    FalconAngles theta;
    for (size_t i = 0; i < 3; ++i) theta[i] = falconEncoderToAngle(rep.encoder[i]);
    const FalconFkResult fk = falconForwardKinematics(theta, position_m_);
    pose_ok_ = fk.converged;
    if (fk.converged) {
        position_m_ = fk.position_m;
        angles_ = theta;
    } else {
        ++stats_.solver_fallbacks;
    }
}

ReadStatus FalconDevice::read(double loop_time_s, DeviceState& out) noexcept {
    if (!link_ || failed_) return ReadStatus::kFailed;
    if (awaiting_) {
        const UsbResult r = link_->read(buf_, options_.tick_read_timeout_ms);
        if (r.status == UsbStatus::kNoDevice) {
            unplugged_ = true;
            fail("the Falcon was unplugged or lost power during the session");
            return ReadStatus::kFailed;
        }
        if (r.status == UsbStatus::kError) ++stats_.usb_errors;
        parser_.push(std::span<const uint8_t>(buf_.data(), r.bytes));
    }
    bool fresh = false;
    FalconReport rep;
    while (parser_.next(rep)) {
        takeFrame(rep);
        fresh = true;
    }
    stats_.bytes_discarded = parser_.bytesDiscarded();
    if (fresh) {
        awaiting_ = false;
        silent_ = 0;
    } else {
        ++stats_.ticks_without_frame;
        stats_.max_silent_ticks = std::max(stats_.max_silent_ticks, ++silent_);
        if (silent_ >= uint64_t(options_.silent_ticks_to_fail)) {
            fail("the Falcon stopped answering (no packet for a quarter of a second)");
            return ReadStatus::kFailed;
        }
    }
    if (homed_) ++stats_.ticks_homed;
    out.t_s = loop_time_s;
    out.position_m = position_m_;
    out.buttons = report_.buttons;
    out.homed = homed_;
    out.stale_ticks = uint32_t(std::min<uint64_t>(silent_, UINT32_MAX));
    return ReadStatus::kOk;
}

bool FalconDevice::writeForce(const Vec3& force_N) noexcept {
    if (!link_ || failed_) return false;
    FalconCommand cmd;
    cmd.status = statusBits();
    bool accepted = true;
    const double magnitude = glm::length(force_N);
    if (!std::isfinite(magnitude)) {
        accepted = false;  // zero motors
    } else if (!homed_) {
        if (magnitude > 0.0) {
            ++stats_.refused_forces;
            accepted = false;
        }
    } else if (silent_ >= uint64_t(options_.stale_ticks_to_zero)) {
        // The position has not been heard for a while: a force from it
        // would push on blind. Zero motors until a frame comes again.
        if (magnitude > 0.0) ++stats_.stale_zeroed;
    } else if (pose_ok_) {
        const double limit = limits().max_force_N;
        const Vec3 f = magnitude > limit ? force_N * (limit / magnitude) : force_N;
        const FalconMotorOutput m =
            falconMotorCommands(position_m_, angles_, f, options_.counts_per_Nm, options_.max_motor_command);
        if (m.valid) cmd.motor = m.command;
        if (m.limited) ++stats_.limited_commands;
    }
    if (!awaiting_ || ++since_sent_ >= options_.resend_after_ticks) {
        if (awaiting_) ++stats_.resends;
        if (!send(cmd)) return false;
    }
    return accepted;
}

}  // namespace tsf::haptics
