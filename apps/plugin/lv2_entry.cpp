// The LV2 bundle's entry point: DPF's descriptor (compiled as dpf_lv2_descriptor, see
// CMakeLists.txt) with KXStudio's programs interface left out.
//
// Why: LV2 lets a host call that interface's select_program from its audio thread, and with
// the full state DPF's select_program asks the plugin for its state text right after the
// program (getState builds the preset text, and DPF's String copies it: allocations). The
// programs are in the bundle as LV2 presets already (DPF's ttl generator writes each one's
// control values and state to presets.ttl), which hosts load through the state interface,
// off the audio thread. VST3 keeps its programs (DPF's VST3 wrapper does not ask for the state
// on a program change).
#undef lv2_descriptor  // the name CMakeLists.txt gives DPF's, for this file's own

#include <cstring>

#include "src/lv2/lv2.h"  // DPF's copies of the LV2 headers, as its descriptor is built with
#include "src/lv2/lv2_programs.h"

extern "C" const LV2_Descriptor* dpf_lv2_descriptor(uint32_t index);

namespace {

const LV2_Descriptor* dpf_descriptor() {
    static const LV2_Descriptor* const dpf = dpf_lv2_descriptor(0);
    return dpf;
}

// Any thread: DPF's extension data but the programs interface.
const void* extension_data(const char* uri) {
    if (std::strcmp(uri, LV2_PROGRAMS__Interface) == 0) return nullptr;
    return dpf_descriptor()->extension_data(uri);
}

}  // namespace

LV2_SYMBOL_EXPORT const LV2_Descriptor* lv2_descriptor(uint32_t index) {
    static const LV2_Descriptor tactus = [] {
        LV2_Descriptor descriptor = *dpf_descriptor();
        descriptor.extension_data = extension_data;
        return descriptor;
    }();
    return index == 0 ? &tactus : nullptr;
}
