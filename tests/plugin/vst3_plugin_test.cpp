// The VST3 binary as a VST3 host opens it (through the VST3 ABI as DPF's travesty headers
// describe it): ModuleEntry, GetPluginFactory, the component and its edit controller, which
// lists the table's parameters: DPF puts its own few (latency, program) first, so a parameter's
// VST3 id is its stable id plus that fixed offset, never its place in the table; titles, units,
// defaults, steps and the bypass flag come from the table.
#include <dlfcn.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "tactus/params/params.hpp"
#include "travesty/base.h"
#include "travesty/component.h"
#include "travesty/edit_controller.h"
#include "travesty/factory.h"

namespace tactus::test {
namespace {

std::string ascii(const int16_t* utf16) {
    std::string s;
    for (; *utf16; ++utf16) s += static_cast<char>(*utf16);
    return s;
}

TEST(Vst3Plugin, TheControllerListsTheTableByStableId) {
    void* module = dlopen(TACTUS_PLUGIN_VST3, RTLD_NOW | RTLD_LOCAL);
    ASSERT_NE(module, nullptr) << dlerror();
    auto entry = reinterpret_cast<bool (*)(void*)>(dlsym(module, "ModuleEntry"));
    auto exit = reinterpret_cast<bool (*)()>(dlsym(module, "ModuleExit"));
    auto get_factory =
        reinterpret_cast<v3_plugin_factory** (*)()>(dlsym(module, "GetPluginFactory"));
    ASSERT_TRUE(entry && exit && get_factory);
    ASSERT_TRUE(entry(module));
    v3_plugin_factory** factory = get_factory();
    ASSERT_NE(factory, nullptr);
    ASSERT_EQ(v3_cpp_obj(factory)->num_classes(factory), 1);
    v3_class_info info{};
    ASSERT_EQ(v3_cpp_obj(factory)->get_class_info(factory, 0, &info), V3_OK);
    EXPECT_EQ(std::string(info.name), "tactus");

    v3_component** component = nullptr;
    ASSERT_EQ(v3_cpp_obj(factory)->create_instance(factory, info.class_id, v3_component_iid,
                                                   reinterpret_cast<void**>(&component)),
              V3_OK);
    ASSERT_EQ(v3_cpp_obj_initialize(component, nullptr), V3_OK);
    // Without a UI, DPF's component is its own edit controller (a host asks it first).
    v3_edit_controller** controller = nullptr;
    ASSERT_EQ(v3_cpp_obj_query_interface(component, v3_edit_controller_iid, &controller), V3_OK);
    ASSERT_NE(controller, nullptr);

    const int32_t count = v3_cpp_obj(controller)->get_parameter_count(controller);
    uint32_t largest = 0;
    for (const ParamSpec& s : param_table()) largest = std::max(largest, s.id);
    // The plugin's parameters follow DPF's own: the bypass (index 0) is the first of them.
    int32_t offset = -1;
    for (int32_t i = 0; i < count && offset < 0; ++i) {
        v3_param_info p{};
        ASSERT_EQ(v3_cpp_obj(controller)->get_parameter_info(controller, i, &p), V3_OK);
        if (p.flags & V3_PARAM_IS_BYPASS) offset = i;
    }
    ASSERT_GE(offset, 0) << "no bypass parameter";
    ASSERT_EQ(count - offset, static_cast<int32_t>(largest + 1));
    int listed = 0;
    for (const ParamSpec& s : param_table()) {
        v3_param_info p{};
        const int32_t index = offset + static_cast<int32_t>(s.id);
        ASSERT_EQ(v3_cpp_obj(controller)->get_parameter_info(controller, index, &p), V3_OK);
        EXPECT_EQ(p.param_id, static_cast<v3_param_id>(index));
        EXPECT_EQ(ascii(p.title), s.key);
        EXPECT_EQ(ascii(p.units), s.unit) << s.key;
        EXPECT_TRUE(p.flags & V3_PARAM_CAN_AUTOMATE) << s.key;
        if (s.type != ParamType::real) {
            EXPECT_EQ(p.step_count, static_cast<int32_t>(std::lround(s.max - s.min))) << s.key;
        }
        const double plain =
            v3_cpp_obj(controller)
                ->normalised_parameter_to_plain(controller, p.param_id, p.default_normalised_value);
        EXPECT_NEAR(plain, s.default_value, 1e-6 * (s.max - s.min))
            << s.key;  // normalised in floats
        ++listed;
    }
    std::printf(
        "VST3 controller: %d parameters; the bypass at id %d, the table's %d at their "
        "stable id + %d\n",
        count, offset, listed, offset);

    v3_cpp_obj_unref(controller);
    v3_cpp_obj_terminate(component);
    v3_cpp_obj_unref(component);
    v3_cpp_obj_unref(factory);
    EXPECT_TRUE(exit());
    dlclose(module);
}

}  // namespace
}  // namespace tactus::test
