// numpy arrays as the engine reads and writes audio: one pointer per channel; the one place
// every Python call converts its audio. Audio is (frames,) or (frames, channels): float of any
// width as it is, integers scaled to full scale as libsndfile scales an audio file's (int16 by
// 1/32768, int32 by 2^-31, uint8 as (x - 128) / 128); complex, non-numeric, NaN and infinite
// samples refused. A float32 array whose channels are contiguous (1-D, one column, or Fortran
// order) is read in place, anything else is converted once. Outputs are (frames, channels)
// float32 in Fortran order, so the engine writes each channel in place.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <vector>

namespace tactus::python {

using AudioArray = pybind11::array_t<float, pybind11::array::f_style | pybind11::array::forcecast>;

struct AudioView {
    AudioArray array;  // keeps the samples alive
    int frames = 0, channels = 0;
    std::vector<const float*> pointers;
};

// ValueError (naming what is wrong, and for a non-finite sample where) for anything but 1 or 2
// dimensions, no channels, or samples that are not audio.
AudioView audio_view(const pybind11::handle& x);

struct AudioOutput {
    AudioArray array;
    std::vector<float*> pointers;
};
AudioOutput audio_output(int frames, int channels);

}  // namespace tactus::python
