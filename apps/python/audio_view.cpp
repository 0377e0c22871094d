#include "audio_view.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>

namespace py = pybind11;

namespace tactus::python {
namespace {

// Integer samples scaled as libsndfile scales an audio file's (SFC_SET_NORM_FLOAT): signed by
// 2^-(bits-1), unsigned 8-bit (WAV's) offset by 128 first, so full scale is -1 ... 1 whatever
// the type (scipy.io.wavfile.read gives int16, int32 with 24-bit data left-justified, or
// uint8). Other integer types are no audio file's samples: refused rather than guessed.
AudioArray scaled_integers(const py::array& x) {
    const py::dtype type = x.dtype();
    const auto bits = static_cast<int>(8 * type.itemsize());
    const bool is_signed = type.kind() == 'i';
    if ((is_signed && bits > 32) || (!is_signed && bits != 8))
        throw py::value_error(fmt::format(
            "audio: {} samples have no audio scale; give float (-1 to 1), int8, int16, int32 "
            "or uint8",
            type.attr("name").cast<std::string>()));
    const float offset = is_signed ? 0.0f : 128.0f;
    const float scale = std::ldexp(1.0f, 1 - bits);
    // A float32 copy in the engine's layout, scaled in place.
    AudioArray out = AudioArray::ensure(x.attr("astype")("float32", py::arg("order") = "F"));
    float* data = out.mutable_data();
    for (py::ssize_t i = 0; i < out.size(); ++i) data[i] = (data[i] - offset) * scale;
    return out;
}

// Float samples as they are (read in place when already float32 in the engine's layout).
AudioArray as_audio(const py::handle& x) {
    const py::array any = py::array::ensure(x);
    if (!any) throw py::value_error("audio: expected an array of samples");
    switch (any.dtype().kind()) {
        case 'f':
            return AudioArray::ensure(any);
        case 'i':
        case 'u':
            return scaled_integers(any);
        case 'c':
            throw py::value_error(
                "audio: complex samples; give real ones (x.real, or abs(x) for a magnitude)");
        default:
            throw py::value_error(fmt::format("audio: expected numbers, got {} samples",
                                              any.dtype().attr("name").cast<std::string>()));
    }
}

// NaN or infinite samples would give silent output (the engine reads them as 0): refused.
void check_finite(const AudioView& view) {
    for (int c = 0; c < view.channels; ++c)
        for (int i = 0; i < view.frames; ++i)
            if (const float v = view.pointers[c][i]; !std::isfinite(v))
                throw py::value_error(
                    fmt::format("audio: sample {} of channel {} is {}; give finite samples "
                                "(numpy.nan_to_num(x) replaces them)",
                                i, c,
                                std::isnan(v) ? "NaN"
                                : v > 0       ? "+inf"
                                              : "-inf"));
}

}  // namespace

AudioView audio_view(const py::handle& x) {
    AudioView view{as_audio(x), 0, 0, {}};
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
    check_finite(view);
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
