# imess::warnings — the warning set every target in the tree compiles with;
# IMESS_SANITIZE adds ASan + UBSan to everything that links it.
add_library(imess_warnings INTERFACE)
add_library(imess::warnings ALIAS imess_warnings)
target_compile_options(imess_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wnon-virtual-dtor -Wcast-align
  -Wunused -Woverloaded-virtual -Wdouble-promotion
  -Wimplicit-fallthrough)
if(IMESS_SANITIZE)
  target_compile_options(imess_warnings INTERFACE -fsanitize=address,undefined -fno-omit-frame-pointer)
  target_link_options(imess_warnings INTERFACE -fsanitize=address,undefined)
endif()
