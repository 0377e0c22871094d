# Run after DPF's ttl generator: takes KXStudio's programs interface out of the bundle's
# extension data, as lv2_entry.cpp takes it out of the binary (the programs are the bundle's
# presets). Usage: cmake -DBUNDLE=<the .lv2 directory> -P strip_programs_interface.cmake
file(GLOB ttls ${BUNDLE}/*.ttl)
foreach(ttl ${ttls})
  file(READ ${ttl} text)
  string(REGEX REPLACE
         "[ \t\r\n]*,[ \t\r\n]*<http://kxstudio\\.sf\\.net/ns/lv2ext/programs#Interface>" ""
         stripped "${text}")
  if(stripped MATCHES "programs#Interface")
    message(FATAL_ERROR "${ttl}: the programs interface is still listed")
  endif()
  if(NOT stripped STREQUAL text)
    file(WRITE ${ttl} "${stripped}")
  endif()
endforeach()
