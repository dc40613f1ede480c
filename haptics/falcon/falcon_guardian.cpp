#include "haptics/falcon/falcon_guardian.h"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <thread>

#include "haptics/falcon/falcon_packet.h"
#include "haptics/falcon/ftdi_link.h"

namespace tsf::haptics {
namespace {

constexpr char kReleased = 'R';
/// Opening is tried this often, this far apart (about 2 s in all).
constexpr int kOpenTries = 100;
constexpr auto kOpenRetry = std::chrono::milliseconds(20);
constexpr int kWriteTimeout_ms = 5;
constexpr int kReplyTimeout_ms = 5;

[[noreturn]] void guard(int fd, const UsbOpener& opener) {
    ::setsid();  // its own session and process group: no terminal's signals reach it
    for (int sig : {SIGHUP, SIGINT, SIGQUIT, SIGTSTP, SIGPIPE}) ::signal(sig, SIG_IGN);
    ::signal(SIGTERM, SIG_DFL);
    if (const int null = ::open("/dev/null", O_RDWR); null >= 0) {
        ::dup2(null, STDIN_FILENO);
        ::dup2(null, STDOUT_FILENO);  // a pipe the caller reads must end with the session
        ::close(null);
    }
    char c = 0;
    ssize_t n;
    do n = ::read(fd, &c, 1);
    while (n < 0 && errno == EINTR);
    if (n == 1 && c == kReleased) ::_exit(0);
    const int sent = writeFalconZeroPackets(opener, kGuardianZeroPackets);
    if (sent > 0)
        std::fprintf(stderr, "tsf: the feel session ended without closing the Falcon; its guardian set it to zero "
                             "force (%d packets)\n", sent);
    else
        std::fprintf(stderr, "tsf: the feel session ended without closing the Falcon and its guardian could not "
                             "reach it: switch the Falcon's power off\n");
    ::_exit(sent > 0 ? 0 : 1);
}

}  // namespace

int writeFalconZeroPackets(const UsbOpener& opener, int packets) noexcept {
    std::unique_ptr<UsbTransport> usb;
    for (int k = 0; k < kOpenTries && !usb; ++k) {
        try {
            usb = opener();
        } catch (...) {
            std::this_thread::sleep_for(kOpenRetry);
        }
    }
    if (!usb) return 0;
    FtdiLink link(*usb);
    const FalconPacket zero = encodeFalconCommand(FalconCommand{{0, 0, 0}, uint8_t(kFalconHoming | kFalconLedRed)});
    std::array<uint8_t, FtdiLink::kDataBytes> buf{};
    int sent = 0;
    for (int k = 0; k < packets; ++k) {
        const UsbResult w = link.write(zero, kWriteTimeout_ms);
        if (w.status == UsbStatus::kNoDevice) break;
        if (w.ok()) ++sent;
        if (link.read(buf, kReplyTimeout_ms, kFalconPacketBytes).status == UsbStatus::kNoDevice) break;
    }
    return sent;
}

FalconGuardian::FalconGuardian(UsbOpener opener) {
    int fds[2];
    if (::pipe2(fds, O_CLOEXEC) != 0)
        throw DeviceError(std::string("cannot start the process that zeroes the Falcon should tsf die: ") +
                          std::strerror(errno));
    std::fflush(nullptr);  // nothing buffered is written twice
    const pid_t pid = ::fork();
    if (pid < 0) {
        const int e = errno;
        ::close(fds[0]);
        ::close(fds[1]);
        throw DeviceError(std::string("cannot start the process that zeroes the Falcon should tsf die: ") +
                          std::strerror(e));
    }
    if (pid == 0) {
        ::close(fds[1]);  // the session process must be the pipe's only writer
        guard(fds[0], opener);
    }
    ::close(fds[0]);
    fd_ = fds[1];
    pid_ = pid;
}

FalconGuardian::~FalconGuardian() { release(); }

void FalconGuardian::release() noexcept {
    if (fd_ < 0) return;
    ssize_t n;
    do n = ::write(fd_, &kReleased, 1);
    while (n < 0 && errno == EINTR);
    ::close(fd_);
    fd_ = -1;
    int status = 0;
    while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
    }
}

}  // namespace tsf::haptics
