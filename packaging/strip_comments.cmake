# CPack pre-build script: removes the compiler's .comment and .note sections from the staged
# programs, as Debian's dh_strip does (CPACK_STRIP_FILES strips only the symbols).
file(GLOB programs "${CPACK_TEMPORARY_DIRECTORY}/usr/bin/*")
find_program(objcopy NAMES objcopy REQUIRED)
foreach(p ${programs})
  execute_process(COMMAND ${objcopy} --remove-section=.comment --remove-section=.note ${p} RESULT_VARIABLE rc)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "objcopy could not remove .comment and .note from ${p}")
  endif()
endforeach()
