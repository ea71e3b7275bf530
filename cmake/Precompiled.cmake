# Precompiled headers: the heavy third-party headers (Eigen, Asio, spdlog, nlohmann-json, Catch2)
# and the common standard ones are parsed once per target instead of once per source file.
# IMESS_PCH=OFF builds without them (to check that every file includes what it uses).
option(IMESS_PCH "Precompile the heavy third-party headers per target" ON)

set(imess_pch_std <algorithm> <array> <chrono> <cmath> <cstdint> <cstdio> <functional> <map>
    <memory> <optional> <sstream> <string> <string_view> <utility> <variant> <vector>)

# imess_precompile(<target> [<header>...]): the standard headers above plus the given ones
# (angle brackets: <Eigen/Dense>) precompiled for every source of <target>.
function(imess_precompile target)
  if(IMESS_PCH)
    target_precompile_headers(${target} PRIVATE ${imess_pch_std} ${ARGN})
  endif()
endfunction()

# imess_reuse_precompiled(<target> <from>): <target> uses <from>'s precompiled header (same
# flags and definitions: the test executables share one).
function(imess_reuse_precompiled target from)
  if(IMESS_PCH)
    target_precompile_headers(${target} REUSE_FROM ${from})
  endif()
endfunction()

if(IMESS_PCH)   # a precompiled header GCC cannot use is parsed as text, silently slow: say so
  target_compile_options(imess_warnings INTERFACE -Winvalid-pch)
endif()
