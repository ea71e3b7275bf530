// Opening a serial device (a USB-serial adapter, a UART, a pseudo-terminal) for a card link:
// raw mode (8N1, no flow control, no echo, no line editing), the baud rate set, non-blocking,
// held exclusively (flock) so a second messd cannot share the line. Set-up only: throws.
#pragma once
#include <stdexcept>
#include <string>

namespace imess::hal {

class SerialLineError : public std::runtime_error {
 public:
  // Missing, NotATty and BadBaud are the configuration's fault; Busy and Failed are not.
  enum class Kind { Missing, NotATty, Busy, BadBaud, Failed };
  SerialLineError(Kind kind, const std::string& what) : std::runtime_error(what), kind_(kind) {}
  Kind kind() const noexcept { return kind_; }
  bool configuration() const noexcept { return kind_ == Kind::Missing || kind_ == Kind::NotATty || kind_ == Kind::BadBaud; }

 private:
  Kind kind_;
};

// The baud rates a line may be set to (termios' standard ones from 9600 up).
bool serial_baud_supported(int baud) noexcept;
const char* serial_bauds_text() noexcept;  // "9600, 19200, …" for messages

// Opens path, configures it and returns the descriptor; throws SerialLineError naming the
// device and what is wrong (missing, not a terminal, in use by another process, …).
int open_serial_line(const std::string& path, int baud);

}  // namespace imess::hal
