// A small LV2 host for the plugin tests, on lilv: it offers what DPF's plugins need and
// lv2apply does not (urid:map, options with the block lengths and sample rate, bounded block
// length, a worker run at once), connects every port (control inputs at their defaults),
// runs blocks, sets control ports by symbol, sets a path property with patch:Set as a host's
// file chooser does, and saves and restores state and presets through lilv as LV2 hosts do.
#pragma once

#include <lilv/lilv.h>
#include <lv2/atom/atom.h>
#include <lv2/atom/forge.h>
#include <lv2/atom/util.h>
#include <lv2/buf-size/buf-size.h>
#include <lv2/core/lv2.h>
#include <lv2/options/options.h>
#include <lv2/parameters/parameters.h>
#include <lv2/patch/patch.h>
#include <lv2/presets/presets.h>
#include <lv2/state/state.h>
#include <lv2/urid/urid.h>
#include <lv2/worker/worker.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace tactus::test {

class Lv2World {
  public:
    explicit Lv2World(const std::filesystem::path& bundle) : world_(lilv_world_new()) {
        std::string dir = std::filesystem::absolute(bundle).string();
        if (dir.back() != '/') dir += '/';
        LilvNode* uri = lilv_new_file_uri(world_, nullptr, dir.c_str());
        lilv_world_load_bundle(world_, uri);
        lilv_node_free(uri);
        const LilvPlugins* plugins = lilv_world_get_all_plugins(world_);
        if (lilv_plugins_size(plugins) != 1) throw std::runtime_error(dir + ": not one plugin");
        plugin_ = lilv_plugins_get(plugins, lilv_plugins_begin(plugins));
    }
    ~Lv2World() {
        nodes_.clear();
        lilv_world_free(world_);
    }
    Lv2World(const Lv2World&) = delete;
    Lv2World& operator=(const Lv2World&) = delete;

    LilvWorld* world() const { return world_; }
    const LilvPlugin* plugin() const { return plugin_; }
    LilvNode* node(const char* uri) {
        auto& n = nodes_[uri];
        if (!n) n.reset(lilv_new_uri(world_, uri));
        return n.get();
    }
    // The bundle's presets by label.
    std::map<std::string, std::string> presets() {
        std::map<std::string, std::string> result;
        LilvNodes* related = lilv_plugin_get_related(plugin_, node(LV2_PRESETS__Preset));
        LILV_FOREACH(nodes, i, related) {
            const LilvNode* preset = lilv_nodes_get(related, i);
            lilv_world_load_resource(world_, preset);
            LilvNodes* labels =
                lilv_world_find_nodes(world_, preset, node(LILV_NS_RDFS "label"), nullptr);
            if (labels && lilv_nodes_size(labels) > 0)
                result[lilv_node_as_string(lilv_nodes_get_first(labels))] =
                    lilv_node_as_uri(preset);
            lilv_nodes_free(labels);
        }
        lilv_nodes_free(related);
        return result;
    }

    // urid:map for every instance of this world.
    LV2_URID map(const char* uri) {
        auto [it, added] = urids_.emplace(uri, static_cast<LV2_URID>(urids_.size() + 1));
        if (added) uris_.push_back(it->first);
        return it->second;
    }
    const char* unmap(LV2_URID urid) const {
        return urid >= 1 && urid <= uris_.size() ? uris_[urid - 1].c_str() : nullptr;
    }
    LV2_URID_Map* map_feature() { return &map_; }
    LV2_URID_Unmap* unmap_feature() { return &unmap_; }

  private:
    struct NodeFree {
        void operator()(LilvNode* n) const { lilv_node_free(n); }
    };
    LilvWorld* world_;
    const LilvPlugin* plugin_ = nullptr;
    std::map<std::string, std::unique_ptr<LilvNode, NodeFree>> nodes_;
    std::map<std::string, LV2_URID> urids_;
    std::vector<std::string> uris_;
    LV2_URID_Map map_{this, [](LV2_URID_Map_Handle h, const char* uri) {
                          return static_cast<Lv2World*>(h)->map(uri);
                      }};
    LV2_URID_Unmap unmap_{this, [](LV2_URID_Unmap_Handle h, LV2_URID urid) {
                              return static_cast<Lv2World*>(h)->unmap(urid);
                          }};
};

class Lv2Instance {
  public:
    Lv2Instance(Lv2World& world, double sample_rate_hz, int max_block)
        : world_(world), rate_(static_cast<float>(sample_rate_hz)), block_(max_block) {
        const LV2_URID atom_int = world.map(LV2_ATOM__Int);
        options_ = {{LV2_OPTIONS_INSTANCE, 0, world.map(LV2_BUF_SIZE__minBlockLength),
                     sizeof(int32_t), atom_int, &zero_},
                    {LV2_OPTIONS_INSTANCE, 0, world.map(LV2_BUF_SIZE__maxBlockLength),
                     sizeof(int32_t), atom_int, &block_},
                    {LV2_OPTIONS_INSTANCE, 0, world.map(LV2_BUF_SIZE__nominalBlockLength),
                     sizeof(int32_t), atom_int, &block_},
                    {LV2_OPTIONS_INSTANCE, 0, world.map(LV2_PARAMETERS__sampleRate), sizeof(float),
                     world.map(LV2_ATOM__Float), &rate_},
                    {LV2_OPTIONS_INSTANCE, 0, 0, 0, 0, nullptr}};
        features_store_ = {{LV2_URID__map, world.map_feature()},
                           {LV2_URID__unmap, world.unmap_feature()},
                           {LV2_OPTIONS__options, options_.data()},
                           {LV2_BUF_SIZE__boundedBlockLength, nullptr},
                           {LV2_WORKER__schedule, &schedule_}};
        for (auto& f : features_store_) features_.push_back(&f);
        features_.push_back(nullptr);
        instance_ = lilv_plugin_instantiate(world.plugin(), sample_rate_hz, features_.data());
        if (!instance_) throw std::runtime_error("lilv_plugin_instantiate failed");
        const LilvPlugin* p = world.plugin();
        const uint32_t n = lilv_plugin_get_num_ports(p);
        controls_.resize(n, 0.0f);
        std::vector<float> defaults(n);
        lilv_plugin_get_port_ranges_float(p, nullptr, nullptr, defaults.data());
        for (uint32_t i = 0; i < n; ++i) {
            const LilvPort* port = lilv_plugin_get_port_by_index(p, i);
            const bool input = lilv_port_is_a(p, port, world.node(LV2_CORE__InputPort));
            if (lilv_port_is_a(p, port, world.node(LV2_CORE__AudioPort))) {
                (input ? audio_in_ : audio_out_).push_back(i);
            } else if (lilv_port_is_a(p, port, world.node(LV2_CORE__ControlPort))) {
                controls_[i] = std::isnan(defaults[i]) ? 0.0f : defaults[i];
                symbols_[lilv_node_as_string(lilv_port_get_symbol(p, port))] = i;
                lilv_instance_connect_port(instance_, i, &controls_[i]);
            } else {  // atom ports: an empty sequence in, room for events out
                (input ? atom_in_ : atom_out_).push_back(i);
            }
        }
    }
    ~Lv2Instance() {
        if (active_) lilv_instance_deactivate(instance_);
        lilv_instance_free(instance_);
    }
    Lv2Instance(const Lv2Instance&) = delete;
    Lv2Instance& operator=(const Lv2Instance&) = delete;

    int input_channels() const { return static_cast<int>(audio_in_.size()); }
    int output_channels() const { return static_cast<int>(audio_out_.size()); }
    float& control(const std::string& symbol) { return controls_.at(symbols_.at(symbol)); }
    bool has_control(const std::string& symbol) const { return symbols_.count(symbol) != 0; }

    // The plugin's extension data for `uri` (nullptr when it has none), and its handle.
    const void* extension_data(const char* uri) const {
        return lilv_instance_get_extension_data(instance_, uri);
    }
    LV2_Handle handle() const { return lilv_instance_get_handle(instance_); }

    void activate() {
        lilv_instance_activate(instance_);
        active_ = true;
    }
    void deactivate() {
        lilv_instance_deactivate(instance_);
        active_ = false;
    }
    // One block (0 frames: the plugin only reads its control ports and events).
    void run(const float* const* in, float* const* out, uint32_t frames) {
        for (uint32_t port : atom_in_) {
            std::vector<uint64_t>& buffer = atoms_.emplace_back(kAtomBytes / 8);
            if (!events_.empty()) buffer = std::exchange(events_, {});
            auto* seq = reinterpret_cast<LV2_Atom_Sequence*>(buffer.data());
            if (seq->atom.type == 0)
                seq->atom = {sizeof(LV2_Atom_Sequence_Body), world_.map(LV2_ATOM__Sequence)};
            lilv_instance_connect_port(instance_, port, seq);
        }
        for (uint32_t port : atom_out_) {
            auto* seq =
                reinterpret_cast<LV2_Atom_Sequence*>(atoms_.emplace_back(kAtomBytes / 8).data());
            seq->atom = {kAtomBytes - sizeof(LV2_Atom), world_.map(LV2_ATOM__Chunk)};
            lilv_instance_connect_port(instance_, port, seq);
        }
        for (size_t c = 0; c < audio_in_.size(); ++c)
            lilv_instance_connect_port(instance_, audio_in_[c],
                                       in ? const_cast<float*>(in[c]) : nullptr);
        for (size_t c = 0; c < audio_out_.size(); ++c)
            lilv_instance_connect_port(instance_, audio_out_[c], out ? out[c] : nullptr);
        lilv_instance_run(instance_, frames);
        atoms_.clear();
    }

    // Sets the plugin's path `property` (a URI) to `path` with a patch:Set event in a run of 0
    // frames, as a host's file chooser does; the plugin's worker (run here at once) takes it.
    void set_path(const std::string& property, const std::string& path) {
        events_.assign(kAtomBytes / 8, 0);
        LV2_Atom_Forge forge;
        lv2_atom_forge_init(&forge, world_.map_feature());
        lv2_atom_forge_set_buffer(&forge, reinterpret_cast<uint8_t*>(events_.data()), kAtomBytes);
        LV2_Atom_Forge_Frame sequence, object;
        lv2_atom_forge_sequence_head(&forge, &sequence, 0);
        lv2_atom_forge_frame_time(&forge, 0);
        lv2_atom_forge_object(&forge, &object, 0, world_.map(LV2_PATCH__Set));
        lv2_atom_forge_key(&forge, world_.map(LV2_PATCH__property));
        lv2_atom_forge_urid(&forge, world_.map(property.c_str()));
        lv2_atom_forge_key(&forge, world_.map(LV2_PATCH__value));
        lv2_atom_forge_path(&forge, path.c_str(), static_cast<uint32_t>(path.size() + 1));
        lv2_atom_forge_pop(&forge, &object);
        lv2_atom_forge_pop(&forge, &sequence);
        run(nullptr, nullptr, 0);
    }

    // The plugin's state (its state:interface and its control ports) as an LV2 host saves it.
    LilvState* save_state() {
        return lilv_state_new_from_instance(
            world_.plugin(), instance_, world_.map_feature(), nullptr, nullptr, nullptr, nullptr,
            [](const char* symbol, void* self, uint32_t* size, uint32_t* type) -> const void* {
                auto* me = static_cast<Lv2Instance*>(self);
                *size = sizeof(float);
                *type = me->world_.map(LV2_ATOM__Float);
                return &me->control(symbol);
            },
            this, LV2_STATE_IS_POD | LV2_STATE_IS_PORTABLE, features_.data());
    }
    void restore_state(const LilvState* state) {
        lilv_state_restore(
            state, instance_,
            [](const char* symbol, void* self, const void* value, uint32_t size, uint32_t type) {
                auto* me = static_cast<Lv2Instance*>(self);
                if (size == sizeof(float) && type == me->world_.map(LV2_ATOM__Float) &&
                    me->has_control(symbol))
                    me->control(symbol) = *static_cast<const float*>(value);
            },
            this, 0, features_.data());
    }
    void load_preset(const std::string& uri) {
        LilvNode* node = lilv_new_uri(world_.world(), uri.c_str());
        LilvState* state = lilv_state_new_from_world(world_.world(), world_.map_feature(), node);
        lilv_node_free(node);
        if (!state) throw std::runtime_error(uri + ": no such preset");
        restore_state(state);
        lilv_state_free(state);
    }

  private:
    // The worker, run at once on the calling thread (DPF schedules work only for UI messages).
    static LV2_Worker_Status schedule(LV2_Worker_Schedule_Handle self, uint32_t size,
                                      const void* data) {
        auto* me = static_cast<Lv2Instance*>(self);
        const auto* iface = static_cast<const LV2_Worker_Interface*>(
            lilv_instance_get_extension_data(me->instance_, LV2_WORKER__interface));
        if (!iface) return LV2_WORKER_ERR_UNKNOWN;
        return iface->work(
            lilv_instance_get_handle(me->instance_),
            [](LV2_Worker_Respond_Handle, uint32_t, const void*) { return LV2_WORKER_SUCCESS; },
            nullptr, size, data);
    }

    Lv2World& world_;
    float rate_;
    int32_t block_, zero_ = 0;
    std::vector<LV2_Options_Option> options_;
    LV2_Worker_Schedule schedule_{this, &Lv2Instance::schedule};
    std::vector<LV2_Feature> features_store_;
    std::vector<const LV2_Feature*> features_;
    LilvInstance* instance_ = nullptr;
    std::vector<float> controls_;
    std::map<std::string, uint32_t> symbols_;
    std::vector<uint32_t> audio_in_, audio_out_, atom_in_, atom_out_;
    static constexpr uint32_t kAtomBytes = 8192;
    std::vector<std::vector<uint64_t>> atoms_;  // this run's atom buffers (8-byte aligned)
    std::vector<uint64_t> events_;              // the next run's input events, if any
    bool active_ = false;
};

}  // namespace tactus::test
