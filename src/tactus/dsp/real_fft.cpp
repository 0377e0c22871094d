#include "tactus/dsp/real_fft.hpp"

#include <algorithm>
#include <map>
#include <mutex>
#include <new>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "tactus/dsp/fft_wisdom.hpp"

namespace tactus {
namespace {

// FFTW's planner is not thread-safe; plans are made off the audio thread, one at a time.
std::mutex planner_mutex;

// One pair of plans per size for the whole process, made when the size is first prepared and
// kept to the end (planning costs 10^7 instructions a size, 10^6 with the build's wisdom; every
// RealFft of that size shares them through FFTW's new-array execute functions, which are
// thread-safe). The buffers they are made on come from fftwf_alloc_*, aligned as every RealFft's
// are. planner_mutex held.
struct Plans {
    fftwf_plan forward = nullptr, inverse = nullptr;
};
std::map<int, Plans>& plans() {
    static auto* const made = new std::map<int, Plans>;  // never freed: plans outlive statics
    return *made;
}

// The build's wisdom for `size`, if any.
const char* wisdom_for(int size) {
    const FftWisdom* const end = kFftWisdom + kFftWisdomEntries;
    const FftWisdom* entry = std::lower_bound(kFftWisdom, end, size,
                                              [](const FftWisdom& w, int n) { return w.size < n; });
    return entry != end && entry->size == size ? entry->wisdom : nullptr;
}

// Imports the build's wisdom of the sizes not planned yet, in one text: the first entry's header
// (FFTW's configuration, the same in every entry), every entry's lines, the closing parenthesis.
// The planner takes the plans it records. planner_mutex held.
void import_wisdom(std::span<const int> sizes) {
    std::string text;
    for (int size : sizes) {
        const char* wisdom = size == 0 || plans().contains(size) ? nullptr : wisdom_for(size);
        if (!wisdom) continue;
        const std::string_view entry(wisdom);
        const size_t lines = entry.find('\n') + 1, close = entry.rfind(')');
        if (text.empty()) text = entry.substr(0, lines);
        text += entry.substr(lines, close - lines);
    }
    if (text.empty()) return;
    text += ")\n";
    fftwf_import_wisdom_from_string(text.c_str());
}

// The plans for `size`: made before, or made now. planner_mutex held.
const Plans& plans_for(int size) {
    auto found = plans().find(size);
    if (found != plans().end()) return found->second;
    float* time = fftwf_alloc_real(static_cast<size_t>(size));
    fftwf_complex* spectrum = fftwf_alloc_complex(static_cast<size_t>(size) / 2 + 1);
    if (!time || !spectrum) throw std::bad_alloc();
    const Plans made{fftwf_plan_dft_r2c_1d(size, time, spectrum, FFTW_ESTIMATE),
                     fftwf_plan_dft_c2r_1d(size, spectrum, time, FFTW_ESTIMATE)};
    fftwf_free(time);
    fftwf_free(spectrum);
    if (!made.forward || !made.inverse) throw std::bad_alloc();
    return plans().emplace(size, made).first->second;
}

// The RealFfts prepared on this thread while a PlanTogether lives (its list), waiting for plans.
thread_local std::vector<RealFft*>* waiting = nullptr;

}  // namespace

RealFft::~RealFft() {
    if (waiting) std::erase(*waiting, this);
    release();
}

void RealFft::release() {
    fftwf_free(time_);
    fftwf_free(spectrum_);
    forward_ = inverse_ = nullptr;
    time_ = nullptr;
    spectrum_ = nullptr;
    size_ = 0;
}

void RealFft::take_plans() {
    const Plans& made = plans_for(size_);
    forward_ = made.forward;
    inverse_ = made.inverse;
}

void RealFft::prepare(int size) {
    if (size == size_) return;
    release();
    size_ = size;
    time_ = fftwf_alloc_real(static_cast<size_t>(size));
    spectrum_ = fftwf_alloc_complex(static_cast<size_t>(size) / 2 + 1);
    if (!time_ || !spectrum_) throw std::bad_alloc();
    if (waiting) {
        if (std::find(waiting->begin(), waiting->end(), this) == waiting->end())
            waiting->push_back(this);
    } else {
        std::lock_guard lock(planner_mutex);
        import_wisdom({&size, 1});
        take_plans();
    }
    for (int i = 0; i < size; ++i) time_[i] = 0.0f;
}

RealFft::PlanTogether::PlanTogether() : outer_(waiting) {
    waiting = &waiting_;
}

RealFft::PlanTogether::~PlanTogether() {
    waiting = outer_;
}

void RealFft::PlanTogether::plan() {
    std::vector<int> sizes;
    for (const RealFft* fft : waiting_) sizes.push_back(fft->size_);
    std::sort(sizes.begin(), sizes.end());
    sizes.erase(std::unique(sizes.begin(), sizes.end()), sizes.end());
    std::lock_guard lock(planner_mutex);
    import_wisdom(sizes);
    for (RealFft* fft : waiting_) fft->take_plans();
    waiting_.clear();
}

}  // namespace tactus
