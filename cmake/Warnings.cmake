# imess::warnings — the warning set every target in the tree compiles with; IMESS_SANITIZE
# (address = ASan + UBSan, thread = TSan) and IMESS_FUZZ add their instrumentation to
# everything that links it.
add_library(imess_warnings INTERFACE)
add_library(imess::warnings ALIAS imess_warnings)
target_compile_options(imess_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align
  -Wunused -Woverloaded-virtual -Wdouble-promotion
  -Wimplicit-fallthrough)

if(IMESS_SANITIZE STREQUAL "ON")  # the old boolean form of the option
  set(IMESS_SANITIZE address)
endif()
if(IMESS_SANITIZE STREQUAL "address")
  set(imess_sanitizers -fsanitize=address,undefined -fno-sanitize-recover=undefined)
elseif(IMESS_SANITIZE STREQUAL "thread")
  set(imess_sanitizers -fsanitize=thread)
elseif(IMESS_SANITIZE AND NOT IMESS_SANITIZE MATCHES "^(OFF|off|0|FALSE|false|NO|no)$")
  message(FATAL_ERROR "IMESS_SANITIZE is '${IMESS_SANITIZE}'; accepted: address, thread, or empty")
endif()
if(imess_sanitizers)
  # -g1: line tables only, so a sanitizer's stack trace names file and line (the Dev build type
  # has no debug information) at a fraction of -g's compile time.
  target_compile_options(imess_warnings INTERFACE ${imess_sanitizers} -fno-omit-frame-pointer -g1)
  target_link_options(imess_warnings INTERFACE ${imess_sanitizers})
endif()
if(IMESS_FUZZ)
  if(NOT CMAKE_CXX_COMPILER_ID STREQUAL "Clang")
    message(FATAL_ERROR "IMESS_FUZZ needs clang (libFuzzer); scripts/fuzz configures it")
  endif()
  target_compile_options(imess_warnings INTERFACE -fsanitize=fuzzer-no-link)
endif()
