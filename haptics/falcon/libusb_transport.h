// The real USB transport: libusb-1.0 (the only code in tsf that includes
// libusb.h). Finds the Falcon (FTDI vendor 0x0403, product 0xCB48), detaches
// a kernel driver if one holds it, claims interface 0, and moves data on the
// bulk endpoints 0x02 (OUT) and 0x81 (IN) with synchronous transfers.
#pragma once

#include <cstdint>
#include <memory>

#include "haptics/falcon/usb_transport.h"

namespace tsf::haptics {

inline constexpr uint16_t kFalconVendorId = 0x0403;
inline constexpr uint16_t kFalconProductId = 0xCB48;

/// Opens the first Falcon found. Throws DeviceError saying what to do when
/// there is none ("plug it in, power on, lsusb -d 0403:cb48"), when access
/// is denied (install the udev rule; the message gives the commands), when
/// another program holds it, or when libusb cannot start.
std::unique_ptr<UsbTransport> openFalconUsb();

/// How many Falcons are on the bus (0 when libusb cannot start). For the
/// hardware test, which skips when there is none.
int countFalconsOnUsb() noexcept;

}  // namespace tsf::haptics
