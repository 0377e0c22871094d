#include "tactus/perception/meter.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <tuple>

#include "tactus/core/units.hpp"
#include "tactus/dsp/design_memo.hpp"
#include "tactus/dsp/real_fft.hpp"

namespace tactus::perception {
namespace {

using Gains = std::shared_ptr<const std::vector<double>>;

// The channel's threshold as a displacement gain at each bin of an FFT of `size` points: a
// function of these inputs alone, remembered (a studio re-renders with the same meter often).
Gains threshold_gains(Channel channel, double sample_rate_hz, int size, double contact_area_cm2) {
    static DesignMemo<std::tuple<Channel, double, int, double>, Gains> memo;
    return memo.get(std::tuple(channel, sample_rate_hz, size, contact_area_cm2), [&] {
        auto gains = std::make_shared<std::vector<double>>(static_cast<size_t>(size / 2 + 1));
        const Stimulus stimulus{.contact_area_cm2 = contact_area_cm2};
        for (size_t k = 0; k < gains->size(); ++k)
            (*gains)[k] = db_to_gain(
                threshold_db(channel, static_cast<double>(k) * sample_rate_hz / size, stimulus));
        return Gains(std::move(gains));
    });
}

// A Hann window of n points (shifted half a sample) and its power (sum of squares): remembered,
// as the thresholds are (250 000 sines a prepare for the four windows at 44.1 kHz).
struct Window {
    std::vector<float> values;
    double power = 0;
};
std::shared_ptr<const Window> hann_window(int n) {
    static DesignMemo<int, std::shared_ptr<const Window>> memo;
    return memo.get(n, [&] {
        auto w = std::make_shared<Window>();
        w->values.resize(static_cast<size_t>(n));
        for (int i = 0; i < n; ++i) {
            const double s = std::sin(kPi * (i + 0.5) / n);
            w->values[i] = static_cast<float>(s * s);
            w->power += double(w->values[i]) * w->values[i];
        }
        return std::shared_ptr<const Window>(std::move(w));
    });
}

// sum over k < bins of weight[k] |x[k]|^2, in four partial sums so that each addition need not
// wait for the one before (a long spectrum's sum is otherwise bound by the adder's latency).
double weighted_power(const double* weight, const std::complex<float>* x, int bins) {
    constexpr int kLanes = 4;
    std::array<double, kLanes> sums{};
    int k = 0;
    for (; k + kLanes <= bins; k += kLanes)
        for (int j = 0; j < kLanes; ++j) sums[j] += weight[k + j] * std::norm(x[k + j]);
    for (; k < bins; ++k) sums[0] += weight[k] * std::norm(x[k]);
    return (sums[0] + sums[1]) + (sums[2] + sums[3]);
}

}  // namespace

struct SensationMeter::ChannelState {
    Channel channel = Channel::P;
    int hop_steps = 1;
    RealFft fft;
    std::shared_ptr<const Window> window;  // the process's, shared by meters of its length
    std::vector<double> weight;            // per bin: 2 g_k (D / thr)^2 / (M sum w^2)
    std::vector<double> frames;            // P: the last second of frame values
    size_t next_frame = 0;
    double value = 0;  // latest (peak displacement / threshold)^2
};

SensationMeter::SensationMeter() = default;
SensationMeter::~SensationMeter() = default;

void SensationMeter::prepare(double input_rate_hz, const Calibration& displacement_um,
                             double contact_area_cm2, const Channels& channels) {
    input_rate_hz_ = rate_hz_ = input_rate_hz;
    if (input_rate_hz > kRateHz) {
        resampler_.prepare(input_rate_hz, kRateHz, kChunk);
        rate_hz_ = resampler_.output_rate_hz();
    }
    step_samples_ = static_cast<int>(std::lround(kStepS * rate_hz_));
    channels_.clear();
    int longest = 0;
    for (const auto& info : kChannels) {
        if (!channels[static_cast<size_t>(info.channel)]) continue;
        auto c = std::make_unique<ChannelState>();
        c->channel = info.channel;
        c->hop_steps = kHopSteps[static_cast<int>(info.channel)];
        const int n = kHopsPerWindow * c->hop_steps * step_samples_;
        longest = std::max(longest, n);
        c->fft.prepare(fft_size_at_least(n));
        const int m = c->fft.size();
        c->window = hann_window(n);
        const double window_power = c->window->power;
        c->weight.assign(static_cast<size_t>(c->fft.bins()), 0.0);
        const Gains threshold = threshold_gains(info.channel, rate_hz_, m, contact_area_cm2);
        for (int k = 0; k < c->fft.bins(); ++k) {
            const double f = k * rate_hz_ / m;
            const double ratio = displacement_um(f) / (*threshold)[static_cast<size_t>(k)];
            const double one_sided = (k == 0 || k == m / 2) ? 1.0 : 2.0;
            const double w = 2.0 * one_sided * ratio * ratio / (m * window_power);
            c->weight[k] = std::isfinite(w) ? w : 0.0;
        }
        const int frames_per_second =
            info.channel == Channel::P
                ? static_cast<int>(std::lround(kPIntegrationS / (c->hop_steps * kStepS)))
                : 1;
        c->frames.assign(static_cast<size_t>(frames_per_second), 0.0);
        channels_.push_back(std::move(c));
    }
    history_.prepare(std::max(longest, step_samples_));
    clean_.assign(kChunk, 0.0f);
    reduced_samples_.assign(kChunk, 0.0f);
    resampler_.reset();
    delay_left_ = reduced() ? static_cast<int>(std::lround(resampler_.delay_output_samples())) : 0;
    filled_ = 0;
    steps_ = written_ = 0;
}

void SensationMeter::write(const float* samples, int count,
                           const std::function<void(const MeterReading&)>& on_reading) {
    written_ += count;
    for (int done = 0; done < count;) {
        const int chunk = std::min(count - done, kChunk);
        for (int i = 0; i < chunk; ++i)
            clean_[i] = std::isfinite(samples[done + i]) ? samples[done + i] : 0.0f;
        done += chunk;
        if (reduced()) {
            const int produced = resampler_.process(clean_.data(), chunk, reduced_samples_.data());
            const int skipped = std::min(produced, delay_left_);
            delay_left_ -= skipped;
            meter(reduced_samples_.data() + skipped, produced - skipped, on_reading);
        } else {
            meter(clean_.data(), chunk, on_reading);
        }
    }
}

void SensationMeter::meter(const float* samples, int count,
                           const std::function<void(const MeterReading&)>& on_reading) {
    for (int done = 0; done < count;) {
        const int chunk = std::min(count - done, step_samples_ - filled_);
        history_.write(samples + done, chunk);
        done += chunk;
        if ((filled_ += chunk) == step_samples_) {
            filled_ = 0;
            step(on_reading);
        }
    }
}

void SensationMeter::finish(const std::function<void(const MeterReading&)>& on_reading) {
    // As many readings as the input's own 10 ms steps give, the longest window's silence added.
    const int64_t input_step = std::max<int64_t>(1, std::llround(kStepS * input_rate_hz_));
    const int64_t steps =
        written_ / input_step + int64_t{kHopsPerWindow} * std::max(kHopSteps[0], kHopSteps[1]);
    const std::vector<float> silence(static_cast<size_t>(step_samples_), 0.0f);
    while (steps_ < steps) write(silence.data(), step_samples_, on_reading);
}

void SensationMeter::step(const std::function<void(const MeterReading&)>& on_reading) {
    ++steps_;
    MeterReading reading;
    reading.time_s = static_cast<double>(steps_ * step_samples_) / rate_hz_;
    for (auto& c : channels_) {
        if (steps_ % c->hop_steps == 0) {
            const std::vector<float>& window = c->window->values;
            const int n = static_cast<int>(window.size());
            float* time = c->fft.time();
            history_.read_latest(time, n);
            for (int i = 0; i < n; ++i) time[i] *= window[i];
            std::fill(time + n, time + c->fft.size(), 0.0f);
            c->fft.forward();
            const double power = weighted_power(c->weight.data(), c->fft.spectrum(), c->fft.bins());
            c->frames[c->next_frame] = power;
            if (++c->next_frame == c->frames.size()) c->next_frame = 0;
            double sum = 0;
            for (double v : c->frames) sum += v;
            // P: the last second's energy (temporal summation lowers the threshold of longer
            // stimuli), never more than the window's own: the sensation ends with its stimulus.
            c->value = std::min(power, sum / static_cast<double>(c->frames.size()));
        }
        reading.level_db[static_cast<int>(c->channel)] =
            c->value > 1.0 ? power_to_db(c->value) : 0.0;
    }
    reading.combined_db = combined_sensation_db(reading.level_db);
    on_reading(reading);
}

void MeterSummariser::add(const MeterReading& r) {
    for (size_t c = 0; c < r.level_db.size(); ++c) levels_[c].push_back(r.level_db[c]);
    levels_[4].push_back(r.combined_db);
}

MeterSummary MeterSummariser::summary() const {
    MeterSummary s;
    s.readings = static_cast<int64_t>(levels_[0].size());
    for (size_t c = 0; c < levels_.size(); ++c) {
        ChannelSummary& out = c < 4 ? s.channels[c] : s.combined;
        std::vector<double> engaged;
        for (double v : levels_[c]) {
            out.max_db = std::max(out.max_db, v);
            if (v > 0) engaged.push_back(v);
        }
        if (engaged.empty()) continue;
        out.engaged_fraction = double(engaged.size()) / double(levels_[c].size());
        std::nth_element(engaged.begin(),
                         engaged.begin() + static_cast<std::ptrdiff_t>(engaged.size() / 2),
                         engaged.end());
        out.median_engaged_db = engaged[engaged.size() / 2];
    }
    return s;
}

}  // namespace tactus::perception
