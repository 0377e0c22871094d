// A small CLAP host for the plugin tests: loads a .clap with dlopen, goes through clap_entry and
// the plugin factory as a DAW does, and processes audio in blocks with parameter events, saves
// and loads state through the state extension. Calls the plugin's main-thread functions and its
// audio-thread process() from the calling thread, in the order the CLAP spec allows.
#pragma once

#include <clap/entry.h>
#include <clap/events.h>
#include <clap/ext/audio-ports.h>
#include <clap/ext/latency.h>
#include <clap/ext/params.h>
#include <clap/ext/state.h>
#include <clap/plugin-factory.h>
#include <clap/process.h>
#include <dlfcn.h>

#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "plugin_reference.hpp"

namespace tactus::test {

// The .clap file, its entry initialised for as long as this lives.
// A state in DPF's framing (fields ended by NUL, the whole by 0xfe) holding one of the plugin's
// states, no parameter list beside it: "state" (the TOML) or "layout" (a file's path).
inline std::string dpf_state(const std::string& value, const std::string& key = "state") {
    using namespace std::string_literals;
    return "__dpf_state_begin__\0"s + key + "\0"s + value + "\0__dpf_state_end__\0\xfe"s;
}

class ClapLibrary {
  public:
    explicit ClapLibrary(const std::filesystem::path& path) {
        handle_ = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle_) throw std::runtime_error(std::string("dlopen: ") + dlerror());
        entry_ = static_cast<const clap_plugin_entry_t*>(dlsym(handle_, "clap_entry"));
        if (!entry_ || !entry_->init(path.c_str()))
            throw std::runtime_error(path.string() + ": no clap_entry, or its init failed");
        factory_ =
            static_cast<const clap_plugin_factory_t*>(entry_->get_factory(CLAP_PLUGIN_FACTORY_ID));
        if (!factory_ || factory_->get_plugin_count(factory_) != 1)
            throw std::runtime_error(path.string() + ": no factory with one plugin");
    }
    ~ClapLibrary() {
        entry_->deinit();
        dlclose(handle_);
    }
    ClapLibrary(const ClapLibrary&) = delete;
    ClapLibrary& operator=(const ClapLibrary&) = delete;
    const clap_plugin_factory_t* factory() const { return factory_; }
    const clap_plugin_descriptor_t* descriptor() const {
        return factory_->get_plugin_descriptor(factory_, 0);
    }

  private:
    void* handle_ = nullptr;
    const clap_plugin_entry_t* entry_ = nullptr;
    const clap_plugin_factory_t* factory_ = nullptr;
};

class ClapInstance {
  public:
    explicit ClapInstance(const ClapLibrary& library) {
        host_.host_data = this;
        plugin_ =
            library.factory()->create_plugin(library.factory(), &host_, library.descriptor()->id);
        if (!plugin_ || !plugin_->init(plugin_)) throw std::runtime_error("create_plugin failed");
        params_ = extension<clap_plugin_params_t>(CLAP_EXT_PARAMS);
        state_ = extension<clap_plugin_state_t>(CLAP_EXT_STATE);
        latency_ = extension<clap_plugin_latency_t>(CLAP_EXT_LATENCY);
        ports_ = extension<clap_plugin_audio_ports_t>(CLAP_EXT_AUDIO_PORTS);
        if (!params_ || !state_ || !latency_ || !ports_)
            throw std::runtime_error("plugin lacks params, state, latency or audio-ports");
        for (bool input : {true, false})
            for (uint32_t i = 0, n = ports_->count(plugin_, input); i < n; ++i) {
                clap_audio_port_info_t info{};
                ports_->get(plugin_, i, input, &info);
                (input ? input_buses_ : output_buses_).push_back(info.channel_count);
            }
    }
    ~ClapInstance() {
        if (processing_) plugin_->stop_processing(plugin_);
        if (active_) plugin_->deactivate(plugin_);
        plugin_->destroy(plugin_);
    }
    ClapInstance(const ClapInstance&) = delete;
    ClapInstance& operator=(const ClapInstance&) = delete;

    int input_channels() const { return channels(input_buses_); }
    int output_channels() const { return channels(output_buses_); }
    const clap_plugin_params_t& params() const { return *params_; }
    const clap_plugin_t* plugin() const { return plugin_; }
    uint32_t latency() const { return latency_->get(plugin_); }
    bool restart_requested() const { return restart_requested_; }

    void activate(double sample_rate_hz, uint32_t max_block) {
        if (!plugin_->activate(plugin_, sample_rate_hz, 1, max_block))
            throw std::runtime_error("activate failed");
        active_ = true;
        if (!plugin_->start_processing(plugin_))
            throw std::runtime_error("start_processing failed");
        processing_ = true;
    }

    // One block: `in` and `out` hold input_channels() and output_channels() pointers.
    void process(const float* const* in, float* const* out, uint32_t frames,
                 const std::vector<ParamChange>& changes = {}) {
        stage(in, out, frames, changes);
        process_staged();
    }
    // The same in two steps, so that a test can watch process() alone: stage() builds the
    // block's buffers and events (allocating), process_staged() hands them to the plugin.
    void stage(const float* const* in, float* const* out, uint32_t frames,
               const std::vector<ParamChange>& changes = {}) {
        events_ = events_of(changes);
        inputs_ = buffers(input_buses_, const_cast<float* const*>(in));
        outputs_ = buffers(output_buses_, out);
        process_ = {};
        process_.steady_time = steady_time_;
        process_.frames_count = frames;
        process_.audio_inputs = inputs_.data();
        process_.audio_inputs_count = static_cast<uint32_t>(inputs_.size());
        process_.audio_outputs = outputs_.data();
        process_.audio_outputs_count = static_cast<uint32_t>(outputs_.size());
        process_.in_events = &in_events_;
        process_.out_events = &out_events_;
    }
    void process_staged() {
        if (plugin_->process(plugin_, &process_) == CLAP_PROCESS_ERROR)
            throw std::runtime_error("process failed");
        steady_time_ += process_.frames_count;
    }

    // Parameter changes outside process() (before activation, or between blocks).
    void flush(const std::vector<ParamChange>& changes) {
        events_ = events_of(changes);
        params_->flush(plugin_, &in_events_, &out_events_);
    }

    std::string save_state() const {
        std::string bytes;
        clap_ostream_t stream{&bytes, [](const clap_ostream_t* s, const void* data, uint64_t size) {
                                  static_cast<std::string*>(s->ctx)->append(
                                      static_cast<const char*>(data), size);
                                  return static_cast<int64_t>(size);
                              }};
        if (!state_->save(plugin_, &stream)) throw std::runtime_error("state save failed");
        return bytes;
    }
    bool load_state(const std::string& bytes) {
        std::pair<const std::string*, size_t> source{&bytes, 0};
        clap_istream_t stream{
            &source, [](const clap_istream_t* s, void* data, uint64_t size) {
                auto* src = static_cast<std::pair<const std::string*, size_t>*>(s->ctx);
                const size_t n = std::min<size_t>(size, src->first->size() - src->second);
                std::memcpy(data, src->first->data() + src->second, n);
                src->second += n;
                return static_cast<int64_t>(n);
            }};
        return state_->load(plugin_, &stream);
    }

  private:
    template <class T>
    const T* extension(const char* id) const {
        return static_cast<const T*>(plugin_->get_extension(plugin_, id));
    }
    static int channels(const std::vector<uint32_t>& buses) {
        int n = 0;
        for (uint32_t c : buses) n += static_cast<int>(c);
        return n;
    }
    static std::vector<clap_audio_buffer_t> buffers(const std::vector<uint32_t>& buses,
                                                    float* const* channels) {
        std::vector<clap_audio_buffer_t> result;
        int next = 0;
        for (uint32_t count : buses) {
            clap_audio_buffer_t b{};
            b.data32 = const_cast<float**>(channels + next);
            b.channel_count = count;
            result.push_back(b);
            next += static_cast<int>(count);
        }
        return result;
    }
    static std::vector<clap_event_param_value_t> events_of(
        const std::vector<ParamChange>& changes) {
        std::vector<clap_event_param_value_t> events;
        for (const ParamChange& c : changes) {
            clap_event_param_value_t e{};
            e.header = {sizeof e, c.frame, CLAP_CORE_EVENT_SPACE_ID, CLAP_EVENT_PARAM_VALUE, 0};
            e.param_id = c.id;
            e.note_id = e.port_index = e.channel = e.key = -1;
            e.value = c.value;
            events.push_back(e);
        }
        return events;
    }
    static ClapInstance& self(const clap_host_t* host) {
        return *static_cast<ClapInstance*>(host->host_data);
    }

    const clap_plugin_t* plugin_ = nullptr;
    const clap_plugin_params_t* params_ = nullptr;
    const clap_plugin_state_t* state_ = nullptr;
    const clap_plugin_latency_t* latency_ = nullptr;
    const clap_plugin_audio_ports_t* ports_ = nullptr;
    std::vector<uint32_t> input_buses_, output_buses_;
    bool active_ = false, processing_ = false, restart_requested_ = false;
    int64_t steady_time_ = 0;
    std::vector<clap_event_param_value_t> events_;
    std::vector<clap_audio_buffer_t> inputs_, outputs_;
    clap_process_t process_{};

    const clap_input_events_t in_events_{
        this,
        [](const clap_input_events_t* list) {
            return static_cast<uint32_t>(
                static_cast<const ClapInstance*>(list->ctx)->events_.size());
        },
        [](const clap_input_events_t* list, uint32_t i) {
            return &static_cast<const ClapInstance*>(list->ctx)->events_[i].header;
        }};
    const clap_output_events_t out_events_{
        this, [](const clap_output_events_t*, const clap_event_header_t*) { return true; }};

    static inline const clap_host_latency_t host_latency_{[](const clap_host_t*) {}};
    static inline const clap_host_params_t host_params_{
        [](const clap_host_t*, clap_param_rescan_flags) {},
        [](const clap_host_t*, clap_id, clap_param_clear_flags) {}, [](const clap_host_t*) {}};
    static inline const clap_host_state_t host_state_{[](const clap_host_t*) {}};
    clap_host_t host_{CLAP_VERSION_INIT,
                      nullptr,
                      "tactus test host",
                      "tactus",
                      "",
                      "1",
                      [](const clap_host_t*, const char* id) -> const void* {
                          if (!std::strcmp(id, CLAP_EXT_LATENCY)) return &host_latency_;
                          if (!std::strcmp(id, CLAP_EXT_PARAMS)) return &host_params_;
                          if (!std::strcmp(id, CLAP_EXT_STATE)) return &host_state_;
                          return nullptr;
                      },
                      [](const clap_host_t* host) { self(host).restart_requested_ = true; },
                      [](const clap_host_t*) {},
                      [](const clap_host_t*) {}};
};

}  // namespace tactus::test
