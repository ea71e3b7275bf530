// The three port transports: the shared simulated port space, x86 port instructions and
// Linux ppdev. Set-up errors name the file/device and what to do about them.
#include "imess/hal/port_io.hpp"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>

#if defined(__x86_64__) || defined(__i386__)
#include <sys/io.h>
#define IMESS_HAVE_X86_IO 1
#endif
#if __has_include(<linux/ppdev.h>)
#include <linux/parport.h>
#include <linux/ppdev.h>
#define IMESS_HAVE_PPDEV 1
#endif

namespace imess::hal {

namespace {

// File layout: a 16-byte header, then `count` 16-bit registers.
struct Header {
  char magic[8];
  std::uint16_t base;
  std::uint16_t count;
  std::uint32_t reserved;
};
constexpr char kMagic[8] = {'I', 'M', 'E', 'S', 'S', 'P', 'R', 'T'};
static_assert(sizeof(Header) == 16);
static_assert(std::atomic<std::uint16_t>::is_always_lock_free, "shared registers must be lock-free");

std::string hex(unsigned v) {
  char b[16];
  std::snprintf(b, sizeof b, "0x%X", v);
  return b;
}
std::string sys_error() { return std::strerror(errno); }

}  // namespace

// ------------------------------------------------------------------ shared port space

SharedPortSpace::SharedPortSpace(const std::string& path, std::uint16_t base, int count, Open mode) {
  map(path, mode, base, count);
}

SharedPortSpace::SharedPortSpace(const std::string& path) { map(path, Open::Attach, 0, 0); }

void SharedPortSpace::map(const std::string& path, Open mode, std::uint16_t base, int count) {
  path_ = path;
  if (mode == Open::CreateOwned && (count <= 0 || count > 4096 || base + count > 0x10000))
    throw std::runtime_error("port space: " + std::to_string(count) + " ports from " + hex(base) +
                             " do not fit the 16-bit I/O address space");
  if (path.empty()) {
    if (mode == Open::Attach) throw std::runtime_error("port space: attaching needs a file name");
    size_ = sizeof(Header) + sizeof(std::uint16_t) * static_cast<std::size_t>(count);
    mem_ = mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS, -1, 0);
    if (mem_ == MAP_FAILED) throw std::runtime_error("port space: mmap failed: " + sys_error());
  } else if (mode == Open::CreateOwned) {
    fd_ = open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0666);
    if (fd_ < 0) throw std::runtime_error("port space file " + path + ": cannot create: " + sys_error());
    if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
      close(fd_);
      fd_ = -1;
      throw std::runtime_error("port space file " + path +
                               " is in use by another simulator (messd); give this one its own backend.port_io.file");
    }
    size_ = sizeof(Header) + sizeof(std::uint16_t) * static_cast<std::size_t>(count);
    if (ftruncate(fd_, static_cast<off_t>(size_)) != 0)
      throw std::runtime_error("port space file " + path + ": cannot size: " + sys_error());
    mem_ = mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
    if (mem_ == MAP_FAILED) throw std::runtime_error("port space file " + path + ": mmap failed: " + sys_error());
  } else {
    fd_ = open(path.c_str(), O_RDWR | O_CLOEXEC);
    if (fd_ < 0)
      throw std::runtime_error("port space file " + path + ": " + sys_error() +
                               " (is messd running with a simulated port backend using this file?)");
    struct stat st {};
    if (fstat(fd_, &st) != 0 || static_cast<std::size_t>(st.st_size) < sizeof(Header))
      throw std::runtime_error("port space file " + path + ": too short to be a port space");
    size_ = static_cast<std::size_t>(st.st_size);
    mem_ = mmap(nullptr, size_, PROT_READ | PROT_WRITE, MAP_SHARED, fd_, 0);
    if (mem_ == MAP_FAILED) throw std::runtime_error("port space file " + path + ": mmap failed: " + sys_error());
    auto* h = static_cast<Header*>(mem_);
    if (std::memcmp(h->magic, kMagic, sizeof kMagic) != 0 ||
        sizeof(Header) + 2u * h->count > size_)
      throw std::runtime_error("port space file " + path + ": not an IMESS port space");
    base = h->base;
    count = h->count;
  }
  auto* h = static_cast<Header*>(mem_);
  regs_ = reinterpret_cast<std::atomic<std::uint16_t>*>(static_cast<char*>(mem_) + sizeof(Header));
  if (mode == Open::CreateOwned) {
    std::memcpy(h->magic, kMagic, sizeof kMagic);
    h->base = base;
    h->count = static_cast<std::uint16_t>(count);
    h->reserved = 0;
    for (int i = 0; i < count; ++i) regs_[i].store(0, std::memory_order_relaxed);
  }
  base_ = base;
  count_ = count;
}

SharedPortSpace::~SharedPortSpace() {
  if (mem_ && mem_ != MAP_FAILED) munmap(mem_, size_);
  if (fd_ >= 0) close(fd_);  // releases the lock
}

std::atomic<std::uint16_t>* SharedPortSpace::reg(std::uint16_t port) noexcept {
  if (!contains(port)) {
    count_error();
    return nullptr;
  }
  return &regs_[port - base_];
}

std::uint8_t SharedPortSpace::in8(std::uint16_t port) noexcept {
  auto* r = reg(port);
  return r ? static_cast<std::uint8_t>(r->load(std::memory_order_acquire)) : 0xFF;
}

void SharedPortSpace::out8(std::uint16_t port, std::uint8_t value) noexcept {
  auto* r = reg(port);
  if (!r) return;
  std::uint16_t old = r->load(std::memory_order_relaxed);
  while (!r->compare_exchange_weak(old, static_cast<std::uint16_t>((old & 0xFF00u) | value), std::memory_order_release,
                                   std::memory_order_relaxed)) {
  }
}

std::uint16_t SharedPortSpace::in16(std::uint16_t port) noexcept {
  auto* r = reg(port);
  return r ? r->load(std::memory_order_acquire) : 0xFFFF;
}

void SharedPortSpace::out16(std::uint16_t port, std::uint16_t value) noexcept {
  if (auto* r = reg(port)) r->store(value, std::memory_order_release);
}

std::string SharedPortSpace::describe() const {
  return "simulated port space " + hex(base_) + ".." + hex(base_ + count_ - 1u) +
         (path_.empty() ? std::string(" (private)") : " in " + path_);
}

// ------------------------------------------------------------------ x86 port instructions

X86PortIo::X86PortIo(std::uint16_t base, int count) : base_(base), count_(count) {
#ifdef IMESS_HAVE_X86_IO
  if (count <= 0 || base + count > 0x400)
    throw std::runtime_error("x86 port access: ports " + hex(base) + ".." + hex(base + count - 1u) +
                             " are not all below 0x400, which ioperm() can grant");
  if (ioperm(base, static_cast<unsigned long>(count), 1) != 0) {
    int e = errno;
    throw std::runtime_error("x86 port access to " + hex(base) + ".." + hex(base + count - 1u) + " denied (ioperm: " +
                             std::strerror(e) +
                             "): run messd as root or grant CAP_SYS_RAWIO (setcap cap_sys_rawio+ep messd), "
                             "or use port_io type \"ppdev\"");
  }
#else
  throw std::runtime_error("x86 port access is not available on this processor; use port_io type \"ppdev\"");
#endif
}

X86PortIo::~X86PortIo() {
#ifdef IMESS_HAVE_X86_IO
  ioperm(base_, static_cast<unsigned long>(count_), 0);
#endif
}

std::uint8_t X86PortIo::in8(std::uint16_t port) noexcept {
#ifdef IMESS_HAVE_X86_IO
  if (granted(port, 1)) return inb(port);
#endif
  count_error();
  return 0xFF;
}
void X86PortIo::out8(std::uint16_t port, std::uint8_t value) noexcept {
#ifdef IMESS_HAVE_X86_IO
  if (granted(port, 1)) return outb(value, port);
#endif
  (void)value;
  count_error();
}
std::uint16_t X86PortIo::in16(std::uint16_t port) noexcept {
#ifdef IMESS_HAVE_X86_IO
  if (granted(port, 2)) return inw(port);
#endif
  count_error();
  return 0xFFFF;
}
void X86PortIo::out16(std::uint16_t port, std::uint16_t value) noexcept {
#ifdef IMESS_HAVE_X86_IO
  if (granted(port, 2)) return outw(value, port);
#endif
  (void)value;
  count_error();
}
std::string X86PortIo::describe() const {
  return "x86 ports " + hex(base_) + ".." + hex(base_ + count_ - 1u) + " (ioperm)";
}

// ------------------------------------------------------------------ ppdev

PpdevPortIo::PpdevPortIo(const std::string& device, std::uint16_t base) : device_(device), base_(base) {
#ifdef IMESS_HAVE_PPDEV
  fd_ = open(device.c_str(), O_RDWR | O_CLOEXEC);
  if (fd_ < 0) {
    int e = errno;
    std::string cure = e == ENOENT   ? "the device is missing: load the ppdev module (modprobe ppdev) and check the port number"
                       : e == EACCES ? "permission denied: add the messd user to the group owning it (usually lp)"
                       : e == EBUSY  ? "the port is busy: another program (e.g. the lp printer driver) holds it"
                                     : "check the device";
    throw std::runtime_error("parallel port " + device + ": " + std::strerror(e) + " — " + cure);
  }
  if (ioctl(fd_, PPCLAIM) != 0) {
    int e = errno;
    close(fd_);
    fd_ = -1;
    throw std::runtime_error("parallel port " + device + ": cannot claim it (PPCLAIM: " + std::strerror(e) + ")");
  }
#else
  throw std::runtime_error("ppdev is not available in this build (no <linux/ppdev.h>)");
#endif
}

PpdevPortIo::~PpdevPortIo() {
#ifdef IMESS_HAVE_PPDEV
  if (fd_ >= 0) {
    ioctl(fd_, PPRELEASE);
    close(fd_);
  }
#endif
}

std::uint8_t PpdevPortIo::in8(std::uint16_t port) noexcept {
#ifdef IMESS_HAVE_PPDEV
  unsigned char v = 0xFF;
  int rc = -1;
  switch (port - base_) {
    case 0: rc = ioctl(fd_, PPRDATA, &v); break;
    case 1: rc = ioctl(fd_, PPRSTATUS, &v); break;
    case 2: rc = ioctl(fd_, PPRCONTROL, &v); break;
    default: break;
  }
  if (rc == 0) return v;
#endif
  (void)port;
  count_error();
  return 0xFF;
}

void PpdevPortIo::out8(std::uint16_t port, std::uint8_t value) noexcept {
#ifdef IMESS_HAVE_PPDEV
  unsigned char v = value;
  int rc = -1;
  switch (port - base_) {
    case 0: rc = ioctl(fd_, PPWDATA, &v); break;
    case 2: rc = ioctl(fd_, PPWCONTROL, &v); break;
    default: break;  // the status register is read-only
  }
  if (rc == 0) return;
#endif
  (void)port;
  (void)value;
  count_error();
}

std::uint16_t PpdevPortIo::in16(std::uint16_t) noexcept {
  count_error();
  return 0xFFFF;
}
void PpdevPortIo::out16(std::uint16_t, std::uint16_t) noexcept { count_error(); }
std::string PpdevPortIo::describe() const { return "parallel port " + device_ + " (ppdev) as ports " + hex(base_) + ".." + hex(base_ + 2u); }

std::unique_ptr<PortIo> make_port_io(const PortIoConfig& c) {
  if (c.type == "sim") return std::make_unique<SharedPortSpace>(c.file, c.base, c.count);
  if (c.type == "x86") return std::make_unique<X86PortIo>(c.base, c.count);
  if (c.type == "ppdev") return std::make_unique<PpdevPortIo>(c.device, c.base);
  throw std::runtime_error("port_io type '" + c.type + "' unknown (accepted: sim, x86, ppdev)");
}

}  // namespace imess::hal
