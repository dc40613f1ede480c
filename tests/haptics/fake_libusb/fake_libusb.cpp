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
//   TSF_FAKE_FALCON_REPORT=FILE     what the device saw (key=value lines), kept current: rewritten
//                                   (atomically) at open, after every command and at close, so a
//                                   process killed mid-session leaves the command the device holds
//                                   (last_command, last_command_zero). The report is also the
//                                   device's memory across processes: when it says open=1 (the last
//                                   process never closed the device: it died), the next process to
//                                   open the fake finds the firmware running, the chip's settings
//                                   and the homing as that process left them, as a powered Falcon
//                                   keeps them.
// The grip: a finger held above the workspace until 1.5 s (homing comes
// after 300 packets), then a soft hand (50 N/m toward y = -50 mm, about 2 N
// on the surface) draws a 10 mm circle over the middle at 10 mm/s.
#include <libusb.h>

#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

#include "tests/haptics/fake_falcon.h"
#include "tests/haptics/fake_falcon_report.h"

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

bool g_open = false;   // the device is open in this process (open=1 in the report)
int g_opens = 0;       // how many processes have opened it since the report began

std::map<std::string, std::string> readReport(const std::string& path) {
    return tsf::haptics::testing::readFakeFalconReport(path);
}

void writeReport() {
    const std::string path = env("TSF_FAKE_FALCON_REPORT");
    if (path.empty() || !g_fake) return;
    const std::string tmp = path + ".tmp" + std::to_string(::getpid());
    FILE* f = std::fopen(tmp.c_str(), "w");
    if (!f) return;
    const auto& cmds = g_fake->commands();
    const tsf::haptics::FalconCommand last = cmds.empty() ? tsf::haptics::FalconCommand{} : cmds.back();
    const bool last_zero = last.motor[0] == 0 && last.motor[1] == 0 && last.motor[2] == 0;
    double max_force = 0.0;
    for (const Vec3& v : g_fake->forces()) max_force = std::max(max_force, std::sqrt(v.x * v.x + v.y * v.y + v.z * v.z));
    std::fprintf(f, "controls=%zu\nuploads=%d\nfirmware_bytes=%zu\ncommands=%zu\nlast_command_zero=%d\n"
                    "nonzero_before_homed=%ld\nhomed=%d\nmax_force_N=%.4f\nlowest_homed_y_m=%.5f\nlatency_ms=%d\n"
                    "last_command=%d %d %d\nlast_status=%d\nfirmware_running=%d\ndivisor=%d\nopen=%d\nopens=%d\n"
                    "pid=%ld\n",
                 g_fake->controls().size(), g_fake->uploads(), g_fake->firmwareBytesEchoed(), cmds.size(),
                 int(last_zero), g_fake->nonzeroBeforeHomed(), int(g_fake->homed()), max_force, g_fake->lowestHomedY(),
                 g_fake->latencyTimer(), last.motor[0], last.motor[1], last.motor[2], int(last.status),
                 int(g_fake->firmwareRunning()), int(g_fake->baudDivisor()), int(g_open), g_opens, long(::getpid()));
    if (std::fclose(f) == 0) std::rename(tmp.c_str(), path.c_str());
    else std::remove(tmp.c_str());
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
    cfg.on_command = writeReport;
    // A device the last process never closed (it died) is as that process left it.
    const std::string path = env("TSF_FAKE_FALCON_REPORT");
    const auto before = path.empty() ? std::map<std::string, std::string>{} : readReport(path);
    g_opens = before.count("opens") ? std::atoi(before.at("opens").c_str()) + 1 : 1;
    const auto was = [&](const char* key, const char* fallback) {
        const auto it = before.find(key);
        return it == before.end() ? std::string(fallback) : it->second;
    };
    if (was("open", "0") == "1") {
        cfg.firmware_running = cfg.firmware_running || was("firmware_running", "0") == "1";
        cfg.homed_at_start = was("homed", "0") == "1";
        cfg.divisor_at_start = uint16_t(std::atoi(was("divisor", "16696").c_str()));
        cfg.latency_at_start_ms = std::atoi(was("latency_ms", "16").c_str());
    }
    g_fake = std::make_unique<FakeFalcon>(cfg);
    g_open = true;
    writeReport();
    *handle = new libusb_device_handle;
    return 0;
}

void LIBUSB_CALL libusb_close(libusb_device_handle* handle) {
    g_open = false;
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
