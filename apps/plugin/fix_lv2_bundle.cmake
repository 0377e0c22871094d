# Run after DPF's ttl generator, on the bundle's Turtle. Usage:
#   cmake -DBUNDLE=<the .lv2 directory> -P fix_lv2_bundle.cmake
# 1. Takes KXStudio's programs interface out of the extension data, as lv2_entry.cpp takes it
#    out of the binary (the programs are the bundle's presets).
# 2. The presets hold the settings alone, under the key the plugin restores them from. DPF's
#    generator names each preset's states by the hints of the state numbered as the preset
#    (DistrhoPluginLV2export.cpp: getStateHints(i) for state j), so a preset may file the
#    settings under the layout's host-readable prefix (<URI#state>, which restore never reads),
#    and it writes the empty layout, which a preset must not change, as a string, not a path.
file(GLOB ttls ${BUNDLE}/*.ttl)
foreach(ttl ${ttls})
  file(READ ${ttl} text)
  string(REGEX REPLACE
         "[ \t\r\n]*,[ \t\r\n]*<http://kxstudio\\.sf\\.net/ns/lv2ext/programs#Interface>" ""
         fixed "${text}")
  string(REPLACE "<urn:tactus:vibrotactile#state>" "<urn:distrho:state>" fixed "${fixed}")
  string(REGEX REPLACE "[ \t]*<(urn:distrho:|urn:tactus:vibrotactile#)layout> \"\" ;\n" ""
         fixed "${fixed}")
  if(fixed MATCHES "programs#Interface")
    message(FATAL_ERROR "${ttl}: the programs interface is still listed")
  endif()
  if(ttl MATCHES "presets\\.ttl$" AND fixed MATCHES "(urn:distrho:|vibrotactile#)layout")
    message(FATAL_ERROR "${ttl}: a preset still holds a layout")
  endif()
  if(NOT fixed STREQUAL text)
    file(WRITE ${ttl} "${fixed}")
  endif()
endforeach()
