// A stand-in for libusb-1.0 with a fake Falcon on its bus, preloaded into the
// real tsf binary (LD_PRELOAD) so `tsf feel --device falcon` runs end to end
// - command line, libusb_transport.cpp, the driver, the loop - without
// hardware. Only the calls tsf makes are provided.
//
// Environment:
//   TSF_FAKE_FALCON                 present (default) | absent | access | busy
//   TSF_FAKE_FALCON_RUNNING=1       firmware already running
//   TSF_FAKE_FALCON_FIRMWARE_BYTES  image size that starts the firmware (default: any)
//   TSF_FAKE_FALCON_UNPLUG_AFTER    unplug after this many command packets
//   TSF_FAKE_FALCON_SILENT_AFTER    the firmware hangs after this many command packets: the link
//                                   stays, commands are taken, no reply comes
//   TSF_FAKE_FALCON_REPORT=FILE     on close, write what the device saw (key=value lines)
// The grip: a finger held above the workspace until 1.5 s (homing comes
// after 300 packets), then a soft hand (50 N/m toward y = -50 mm, about 2 N
// on the surface) draws a 10 mm circle over the middle at 10 mm/s.
#include <libusb.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "tests/haptics/fake_falcon.h"

struct libusb_context {
    int unused = 0;
};
struct libusb_device {
    int refs = 1;
};
struct libusb_device_handle {
    bool claimed = false;
};

namespace {

using tsf::haptics::UsbStatus;
using tsf::haptics::Vec3;
using tsf::haptics::testing::FakeFalcon;
using tsf::haptics::testing::FakeFalconConfig;

libusb_device g_device;
std::unique_ptr<FakeFalcon> g_fake;

std::string env(const char* name, const char* fallback = "") {
    const char* v = std::getenv(name);
    return v ? v : fallback;
}

int code(UsbStatus s) {
    switch (s) {
    case UsbStatus::kOk: return LIBUSB_SUCCESS;
    case UsbStatus::kTimeout: return LIBUSB_ERROR_TIMEOUT;
    case UsbStatus::kNoDevice: return LIBUSB_ERROR_NO_DEVICE;
    default: return LIBUSB_ERROR_IO;
    }
}

Vec3 handTarget(double t) {
    if (t < 1.5) return {0.0, 0.02, 0.0};
    const double a = (t - 1.5) * 1.0;  // 10 mm/s on a 10 mm circle
    return {0.01 * std::cos(a), -0.05, 0.01 * std::sin(a)};
}

void writeReport() {
    const std::string path = env("TSF_FAKE_FALCON_REPORT");
    if (path.empty() || !g_fake) return;
    FILE* f = std::fopen(path.c_str(), "w");
    if (!f) return;
    const auto& cmds = g_fake->commands();
    const bool last_zero = cmds.empty() || (cmds.back().motor[0] == 0 && cmds.back().motor[1] == 0 && cmds.back().motor[2] == 0);
    double max_force = 0.0;
    for (const Vec3& v : g_fake->forces()) max_force = std::max(max_force, std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z));
    std::fprintf(f, "controls=%zu\nuploads=%d\nfirmware_bytes=%zu\ncommands=%zu\nlast_command_zero=%d\n"
                    "nonzero_before_homed=%ld\nhomed=%d\nmax_force_N=%.4f\nlowest_homed_y_m=%.5f\nlatency_ms=%d\n",
                 g_fake->controls().size(), g_fake->uploads(), g_fake->firmwareBytesEchoed(), cmds.size(),
                 int(last_zero), g_fake->nonzeroBeforeHomed(), int(g_fake->homed()), max_force, g_fake->lowestHomedY(),
                 g_fake->latencyTimer());
    std::fclose(f);
}

}  // namespace

extern "C" {

int LIBUSB_CALL libusb_init(libusb_context** ctx) {
    if (ctx) *ctx = new libusb_context;
    return 0;
}

void LIBUSB_CALL libusb_exit(libusb_context* ctx) { delete ctx; }

const char* LIBUSB_CALL libusb_error_name(int errcode) {
    switch (errcode) {
    case LIBUSB_ERROR_ACCESS: return "LIBUSB_ERROR_ACCESS";
    case LIBUSB_ERROR_BUSY: return "LIBUSB_ERROR_BUSY";
    case LIBUSB_ERROR_NO_DEVICE: return "LIBUSB_ERROR_NO_DEVICE";
    case LIBUSB_ERROR_TIMEOUT: return "LIBUSB_ERROR_TIMEOUT";
    default: return "LIBUSB_ERROR_OTHER";
    }
}

ssize_t LIBUSB_CALL libusb_get_device_list(libusb_context*, libusb_device*** list) {
    const bool present = env("TSF_FAKE_FALCON", "present") != "absent";
    *list = static_cast<libusb_device**>(std::calloc(2, sizeof(libusb_device*)));
    if (present) (*list)[0] = &g_device;
    return present ? 1 : 0;
}

void LIBUSB_CALL libusb_free_device_list(libusb_device** list, int) { std::free(list); }

libusb_device* LIBUSB_CALL libusb_ref_device(libusb_device* dev) { return dev; }
void LIBUSB_CALL libusb_unref_device(libusb_device*) {}

int LIBUSB_CALL libusb_get_device_descriptor(libusb_device*, struct libusb_device_descriptor* desc) {
    std::memset(desc, 0, sizeof *desc);
    desc->idVendor = 0x0403;
    desc->idProduct = 0xCB48;
    return 0;
}

uint8_t LIBUSB_CALL libusb_get_bus_number(libusb_device*) { return 1; }
uint8_t LIBUSB_CALL libusb_get_device_address(libusb_device*) { return 7; }

int LIBUSB_CALL libusb_open(libusb_device*, libusb_device_handle** handle) {
    if (env("TSF_FAKE_FALCON") == "access") return LIBUSB_ERROR_ACCESS;
    FakeFalconConfig cfg;
    cfg.firmware_running = env("TSF_FAKE_FALCON_RUNNING") == "1";
    cfg.firmware_bytes = size_t(std::atol(env("TSF_FAKE_FALCON_FIRMWARE_BYTES", "0").c_str()));
    cfg.unplug_after_packets = std::atol(env("TSF_FAKE_FALCON_UNPLUG_AFTER", "-1").c_str());
    cfg.silent_after_packets = std::atol(env("TSF_FAKE_FALCON_SILENT_AFTER", "-1").c_str());
    cfg.homing_packets = 300;
    cfg.finger = true;
    cfg.hand_y_N_per_m = 50.0;
    cfg.pose = handTarget;
    g_fake = std::make_unique<FakeFalcon>(cfg);
    *handle = new libusb_device_handle;
    return 0;
}

void LIBUSB_CALL libusb_close(libusb_device_handle* handle) {
    writeReport();
    delete handle;
}

int LIBUSB_CALL libusb_set_auto_detach_kernel_driver(libusb_device_handle*, int) { return 0; }

int LIBUSB_CALL libusb_claim_interface(libusb_device_handle* handle, int) {
    if (env("TSF_FAKE_FALCON") == "busy") return LIBUSB_ERROR_BUSY;
    handle->claimed = true;
    return 0;
}

int LIBUSB_CALL libusb_release_interface(libusb_device_handle* handle, int) {
    handle->claimed = false;
    return 0;
}

int LIBUSB_CALL libusb_control_transfer(libusb_device_handle*, uint8_t request_type, uint8_t request, uint16_t value,
                                        uint16_t index, unsigned char*, uint16_t, unsigned int timeout) {
    if (request_type != 0x40) return LIBUSB_ERROR_INVALID_PARAM;
    return code(g_fake->control(request, value, index, int(timeout)).status);
}

int LIBUSB_CALL libusb_bulk_transfer(libusb_device_handle*, unsigned char endpoint, unsigned char* data, int length,
                                     int* transferred, unsigned int timeout) {
    tsf::haptics::UsbResult r;
    if (endpoint == 0x02) r = g_fake->bulkWrite({data, size_t(length)}, int(timeout));
    else if (endpoint == 0x81) r = g_fake->bulkRead({data, size_t(length)}, int(timeout));
    else return LIBUSB_ERROR_INVALID_PARAM;
    if (transferred) *transferred = int(r.bytes);
    return code(r.status);
}

}  // extern "C"
