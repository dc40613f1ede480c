#include "haptics/falcon/libusb_transport.h"

#include <libusb.h>

#include <cstdio>
#include <string>

#include "haptics/haptic_device.h"

namespace tsf::haptics {
namespace {

constexpr int kInterface = 0;
constexpr unsigned char kEndpointOut = 0x02;
constexpr unsigned char kEndpointIn = 0x81;
constexpr uint8_t kVendorOut = 0x40;  // LIBUSB_REQUEST_TYPE_VENDOR | LIBUSB_RECIPIENT_DEVICE | LIBUSB_ENDPOINT_OUT

/// Where to find the udev rule and how to install it (also in docs/haptics.md).
constexpr const char* kUdevHelp =
    "Install tsf's udev rule, which gives the logged-in user access to the Falcon:\n"
    "  sudo cp " TSF_SOURCE_DIR "/haptics/falcon/70-novint-falcon.rules /etc/udev/rules.d/\n"
    "  (an installed tsf has it in share/tsf/udev/)\n"
    "  sudo udevadm control --reload-rules && sudo udevadm trigger\n"
    "then unplug the Falcon's USB cable and plug it back in (see docs/haptics.md, Linux set-up)";

UsbStatus statusOf(int rc) {
    switch (rc) {
    case LIBUSB_SUCCESS: return UsbStatus::kOk;
    case LIBUSB_ERROR_TIMEOUT: return UsbStatus::kTimeout;
    case LIBUSB_ERROR_NO_DEVICE: return UsbStatus::kNoDevice;
    default: return UsbStatus::kError;
    }
}

struct Context {
    libusb_context* ctx = nullptr;
    ~Context() {
        if (ctx) libusb_exit(ctx);
    }
};

class LibusbTransport final : public UsbTransport {
public:
    LibusbTransport(libusb_context* ctx, libusb_device_handle* h, std::string where)
        : ctx_(ctx), handle_(h), where_(std::move(where)) {}
    ~LibusbTransport() override {
        libusb_release_interface(handle_, kInterface);
        libusb_close(handle_);
        libusb_exit(ctx_);
    }

    UsbResult control(uint8_t request, uint16_t value, uint16_t index, int timeout_ms) noexcept override {
        const int rc = libusb_control_transfer(handle_, kVendorOut, request, value, index, nullptr, 0,
                                               unsigned(timeout_ms));
        return {rc >= 0 ? UsbStatus::kOk : statusOf(rc), 0};
    }
    UsbResult bulkWrite(std::span<const uint8_t> data, int timeout_ms) noexcept override {
        int done = 0;
        // libusb takes a non-const pointer but does not write through it for OUT.
        const int rc = libusb_bulk_transfer(handle_, kEndpointOut, const_cast<unsigned char*>(data.data()),
                                            int(data.size()), &done, unsigned(timeout_ms));
        return {statusOf(rc), size_t(done)};
    }
    UsbResult bulkRead(std::span<uint8_t> buffer, int timeout_ms) noexcept override {
        int done = 0;
        const int rc =
            libusb_bulk_transfer(handle_, kEndpointIn, buffer.data(), int(buffer.size()), &done, unsigned(timeout_ms));
        return {statusOf(rc), size_t(done)};
    }
    const char* location() const noexcept override { return where_.c_str(); }

private:
    libusb_context* ctx_;
    libusb_device_handle* handle_;
    std::string where_;
};

/// The first Falcon on the bus (referenced; the caller unrefs), or null.
libusb_device* findFalcon(libusb_context* ctx, int* count) {
    libusb_device** list = nullptr;
    const ssize_t n = libusb_get_device_list(ctx, &list);
    libusb_device* found = nullptr;
    int falcons = 0;
    for (ssize_t i = 0; i < n; ++i) {
        libusb_device_descriptor d{};
        if (libusb_get_device_descriptor(list[i], &d) != 0) continue;
        if (d.idVendor == kFalconVendorId && d.idProduct == kFalconProductId) {
            if (!found) found = libusb_ref_device(list[i]);
            ++falcons;
        }
    }
    if (list) libusb_free_device_list(list, 1);
    if (count) *count = falcons;
    return found;
}

}  // namespace

int countFalconsOnUsb() noexcept {
    Context c;
    if (libusb_init(&c.ctx) != 0) {
        c.ctx = nullptr;
        return 0;
    }
    int count = 0;
    if (libusb_device* d = findFalcon(c.ctx, &count)) libusb_unref_device(d);
    return count;
}

std::unique_ptr<UsbTransport> openFalconUsb() {
    Context c;
    if (const int rc = libusb_init(&c.ctx); rc != 0) {
        c.ctx = nullptr;
        throw DeviceError(std::string("cannot use USB: libusb failed to start (") + libusb_error_name(rc) +
                          "); on Linux, /dev/bus/usb must exist (inside a container, pass the USB bus through)");
    }
    libusb_device* dev = findFalcon(c.ctx, nullptr);
    if (!dev)
        throw DeviceError(
            "no Novint Falcon found on USB (vendor 0x0403, product 0xcb48). Plug the Falcon's USB cable "
            "directly into the computer (not through an unpowered hub), connect its power supply and switch it "
            "on, then check that `lsusb -d 0403:cb48` lists it. To try tsf without a Falcon, use --device sim");
    char where[64];
    std::snprintf(where, sizeof where, "USB bus %u device %u", unsigned(libusb_get_bus_number(dev)),
                  unsigned(libusb_get_device_address(dev)));
    libusb_device_handle* h = nullptr;
    const int rc = libusb_open(dev, &h);
    libusb_unref_device(dev);
    if (rc == LIBUSB_ERROR_ACCESS)
        throw DeviceError(std::string("permission denied opening the Novint Falcon (") + where + "). " + kUdevHelp);
    if (rc != 0)
        throw DeviceError(std::string("cannot open the Novint Falcon (") + where + "): " + libusb_error_name(rc) +
                          "; unplug it, plug it back in and try again");
    // A kernel serial driver (ftdi_sio) may have bound to the chip: let
    // libusb detach it while we hold the interface (not supported everywhere;
    // claiming then says whether it mattered).
    libusb_set_auto_detach_kernel_driver(h, 1);
    if (const int claim = libusb_claim_interface(h, kInterface); claim != 0) {
        libusb_close(h);
        if (claim == LIBUSB_ERROR_BUSY)
            throw DeviceError(std::string("the Novint Falcon (") + where +
                              ") is in use by another program (another tsf, a libnifalcon or CHAI3D "
                              "application); close it and try again");
        if (claim == LIBUSB_ERROR_ACCESS)
            throw DeviceError(std::string("permission denied claiming the Novint Falcon (") + where + "). " +
                              kUdevHelp);
        throw DeviceError(std::string("cannot claim the Novint Falcon (") + where + "): " +
                          libusb_error_name(claim));
    }
    libusb_context* ctx = c.ctx;
    c.ctx = nullptr;  // owned by the transport now
    return std::make_unique<LibusbTransport>(ctx, h, where);
}

}  // namespace tsf::haptics
