// Real-time safety of the LV2 plugin as a host may drive it: this executable replaces the
// allocation functions and pthread_mutex_lock (support/allocation_counter.cpp), so it is apart
// from lv2_plugin_test.cpp and not built under the sanitizers, which own malloc.
#include <gtest/gtest.h>

#include "lv2/lv2_programs.h"  // DPF's copy of KXStudio's programs extension
#include "lv2_host.hpp"
#include "plugin_reference.hpp"
#include "support/allocation_counter.hpp"

namespace tactus::test {
namespace {

// A host may call a programs interface's select_program from its audio thread, and DPF's (with
// the full state) builds the plugin's state text there. So the bundle has its programs as LV2
// presets only (lv2_plugin_test.cpp loads each): neither its binary nor its ttl offers the programs
// interface. Were one offered, selecting each program here, on the host's audio thread between
// two runs, must allocate and lock nothing.
TEST(Lv2Realtime, NoProgramSelectionAllocatesOrLocksOnTheAudioThread) {
    Lv2World world(TACTUS_PLUGIN_LV2);
    Lv2Instance instance(world, 48000, kBlock);
    instance.activate();
    instance.run(nullptr, nullptr, 0);
    const auto* programs = static_cast<const LV2_Programs_Interface*>(
        instance.extension_data(LV2_PROGRAMS__Interface));
    for (uint32_t index = 0; programs; ++index) {
        const LV2_Program_Descriptor* program = programs->get_program(instance.handle(), index);
        if (!program) break;
        const uint32_t bank = program->bank, number = program->program;
        reset_counts();
        {
            Guard guard;
            programs->select_program(instance.handle(), bank, number);
        }
        EXPECT_EQ(g_allocator_calls.load(), 0) << "allocator calls selecting program " << index;
        EXPECT_EQ(g_mutex_locks.load(), 0) << "locks selecting program " << index;
        instance.run(nullptr, nullptr, 0);
    }
    EXPECT_EQ(programs, nullptr) << "the LV2 binary offers the programs interface";
    EXPECT_FALSE(
        lilv_plugin_has_extension_data(world.plugin(), world.node(LV2_PROGRAMS__Interface)))
        << "the LV2 bundle's ttl lists the programs interface";
}

}  // namespace
}  // namespace tactus::test
