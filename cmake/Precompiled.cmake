# Build speed. Precompiled headers: the heavy third-party headers (Eigen, Asio, spdlog,
# nlohmann-json, Catch2) and the common standard ones are parsed once per target instead of
# once per source file. Unity batches (imess_unity): a target's files compiled a few at a time
# as one, so the templates they share are instantiated once. IMESS_PCH=OFF / IMESS_UNITY=OFF
# build without them (to check that every file includes what it uses and stands alone).
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

# imess_unity(<target> [<batch size>]): <target>'s sources in unity batches (default 6 files).
# Names at file scope (anonymous namespaces too) must then differ between its files.
function(imess_unity target)
  set(batch 6)
  if(ARGC GREATER 1)
    set(batch ${ARGV1})
  endif()
  set_target_properties(${target} PROPERTIES UNITY_BUILD ${IMESS_UNITY} UNITY_BUILD_BATCH_SIZE ${batch})
endfunction()

if(IMESS_PCH)   # a precompiled header GCC cannot use is parsed as text, silently slow: say so
  target_compile_options(imess_warnings INTERFACE -Winvalid-pch)
endif()
