#include "audio_view.hpp"

#include <fmt/format.h>

#include <limits>

namespace py = pybind11;

namespace tactus::python {

AudioView audio_view(const py::handle& x) {
    AudioView view{AudioArray::ensure(x), 0, 0, {}};
    if (!view.array) throw py::value_error("audio: expected an array of samples");
    const py::buffer_info info = view.array.request();
    if (info.ndim != 1 && info.ndim != 2)
        throw py::value_error(fmt::format(
            "audio: expected (frames,) or (frames, channels), got {} dimensions", info.ndim));
    view.frames = static_cast<int>(info.shape[0]);
    view.channels = info.ndim == 2 ? static_cast<int>(info.shape[1]) : 1;
    if (info.shape[0] > std::numeric_limits<int>::max())
        throw py::value_error("audio: more than 2^31 frames; give it in parts");
    if (view.channels < 1) throw py::value_error("audio: no channels");
    const auto* data = static_cast<const float*>(info.ptr);
    for (int c = 0; c < view.channels; ++c)
        view.pointers.push_back(data + static_cast<size_t>(c) * view.frames);
    return view;
}

AudioOutput audio_output(int frames, int channels) {
    AudioOutput out{AudioArray({frames, channels}), {}};
    float* data = out.array.mutable_data();
    for (int c = 0; c < channels; ++c)
        out.pointers.push_back(data + static_cast<size_t>(c) * frames);
    return out;
}

}  // namespace tactus::python
