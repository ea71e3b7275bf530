// PortIo: 8- and 16-bit reads and writes at an I/O address — the transport of the
// parallel-port and drive-kit backends. Three implementations: a simulated port space
// shared through a memory-mapped file, real x86 port instructions, and Linux ppdev.
#pragma once
#include <atomic>
#include <cstdint>
#include <memory>
#include <string>

namespace imess::hal {

class PortIo {
 public:
  virtual ~PortIo() = default;
  // Real-time: noexcept, no allocation, no system call on the simulated space. An access
  // that hits no register reads 0xFF / 0xFFFF (a floating bus) and counts an error.
  virtual std::uint8_t in8(std::uint16_t port) noexcept = 0;
  virtual void out8(std::uint16_t port, std::uint8_t value) noexcept = 0;
  virtual std::uint16_t in16(std::uint16_t port) noexcept = 0;
  virtual void out16(std::uint16_t port, std::uint16_t value) noexcept = 0;
  // Set-up.
  virtual std::string describe() const = 0;
  unsigned long errors() const noexcept { return errors_.load(std::memory_order_relaxed); }

 protected:
  void count_error() noexcept { errors_.fetch_add(1, std::memory_order_relaxed); }

 private:
  std::atomic<unsigned long> errors_{0};
};

// The simulated port space of the MRM manual: `count` ports of 16 bits from `base`.
// A port's 8-bit access reads or writes its low byte (the high byte is kept on out8).
// With a file path the registers live in a shared mapping (MAP_SHARED), so the daemon,
// the simulator and messport see the same registers; with an empty path the mapping is
// private to this process (tests, bench). Every register is a lock-free std::atomic.
class SharedPortSpace final : public PortIo {
 public:
  static constexpr int kDefaultCount = 100;
  enum class Open { CreateOwned, Attach };
  // CreateOwned: creates (or resets) the file, zeroes the registers and takes an exclusive
  // lock so that a second simulator on the same file fails clearly. Attach: maps an
  // existing file (messport); base and count are read from the file's header.
  SharedPortSpace(const std::string& path, std::uint16_t base, int count = kDefaultCount, Open mode = Open::CreateOwned);
  explicit SharedPortSpace(const std::string& path);  // Attach
  ~SharedPortSpace() override;
  SharedPortSpace(const SharedPortSpace&) = delete;
  SharedPortSpace& operator=(const SharedPortSpace&) = delete;

  std::uint8_t in8(std::uint16_t port) noexcept override;
  void out8(std::uint16_t port, std::uint8_t value) noexcept override;
  std::uint16_t in16(std::uint16_t port) noexcept override;
  void out16(std::uint16_t port, std::uint16_t value) noexcept override;
  std::string describe() const override;

  std::uint16_t base() const noexcept { return base_; }
  int count() const noexcept { return count_; }
  bool contains(std::uint16_t port) const noexcept { return port >= base_ && port < base_ + count_; }
  const std::string& path() const noexcept { return path_; }

 private:
  void map(const std::string& path, Open mode, std::uint16_t base, int count);
  std::atomic<std::uint16_t>* reg(std::uint16_t port) noexcept;

  std::string path_;
  std::uint16_t base_ = 0;
  int count_ = 0;
  int fd_ = -1;
  void* mem_ = nullptr;
  std::size_t size_ = 0;
  std::atomic<std::uint16_t>* regs_ = nullptr;
};

// Real x86 port instructions (inb/outb/inw/outw) after ioperm(); needs root or
// CAP_SYS_RAWIO and ports below 0x400. Throws std::runtime_error naming the cure.
class X86PortIo final : public PortIo {
 public:
  X86PortIo(std::uint16_t base, int count);
  ~X86PortIo() override;
  std::uint8_t in8(std::uint16_t port) noexcept override;
  void out8(std::uint16_t port, std::uint8_t value) noexcept override;
  std::uint16_t in16(std::uint16_t port) noexcept override;
  void out16(std::uint16_t port, std::uint16_t value) noexcept override;
  std::string describe() const override;

 private:
  bool granted(std::uint16_t port, int width) const noexcept { return port >= base_ && port + width <= base_ + count_; }
  std::uint16_t base_;
  int count_;
};

// Linux ppdev (/dev/parportN): the parallel port's data (base+0), status (base+1) and
// control (base+2) registers through ioctls; no root needed, only access to the device.
// 16-bit accesses are not supported (count an error). Throws naming the cure.
class PpdevPortIo final : public PortIo {
 public:
  PpdevPortIo(const std::string& device, std::uint16_t base);
  ~PpdevPortIo() override;
  std::uint8_t in8(std::uint16_t port) noexcept override;
  void out8(std::uint16_t port, std::uint8_t value) noexcept override;
  std::uint16_t in16(std::uint16_t port) noexcept override;
  void out16(std::uint16_t port, std::uint16_t value) noexcept override;
  std::string describe() const override;

 private:
  std::string device_;
  std::uint16_t base_;
  int fd_ = -1;
};

struct PortIoConfig {
  std::string type = "sim";             // "sim" | "x86" | "ppdev"
  std::string file;                     // sim: shared register file; "" = private to the process
  std::uint16_t base = 0x300;           // sim: first port of the space; x86/ppdev: first port used
  int count = SharedPortSpace::kDefaultCount;  // sim: ports in the space; x86: ports requested
  std::string device = "/dev/parport0";  // ppdev
};

// Builds the configured port access; throws std::runtime_error with a clear message.
std::unique_ptr<PortIo> make_port_io(const PortIoConfig& config);

}  // namespace imess::hal
