// tactus as a Vamp plugin (vamp-plugin-sdk), for Sonic Visualiser and other Vamp hosts: the
// engine's analysis, vibration program and sensation levels over the waveform. The outputs are
// the columns of `tactus analyze` (io/analysis_rows.hpp), on the analysis hop grid; the
// onsets are those `tactus onsets` prints. Programs are the presets found (default music), the
// parameters the parameter table, generated from it. The vibration is not compensated for an
// actuator, and is metered through the default one (voice-coil), as `tactus analyze` does
// without --actuator. Input: time domain, any channel count (the engine downmixes), any block
// size with step = block.
#pragma once

#include <vamp-sdk/Plugin.h>

#include <memory>
#include <string>
#include <vector>

#include "tactus/io/analysis_rows.hpp"
#include "tactus/params/params.hpp"

namespace tactus::vamp {

class TactusPlugin : public Vamp::Plugin {
  public:
    explicit TactusPlugin(float input_sample_rate);
    ~TactusPlugin() override;

    std::string getIdentifier() const override { return "tactus"; }
    std::string getName() const override { return "tactus: music to vibrotactile feedback"; }
    std::string getDescription() const override;
    std::string getMaker() const override { return "tactus"; }
    std::string getCopyright() const override { return "GPL-3.0-or-later"; }
    int getPluginVersion() const override { return 1; }

    InputDomain getInputDomain() const override { return TimeDomain; }
    size_t getPreferredBlockSize() const override { return 1024; }
    size_t getPreferredStepSize() const override { return 1024; }
    size_t getMaxChannelCount() const override { return kMaxChannels; }

    ParameterList getParameterDescriptors() const override;
    float getParameter(std::string identifier) const override;
    void setParameter(std::string identifier, float value) override;
    ProgramList getPrograms() const override;
    std::string getCurrentProgram() const override { return program_; }
    void selectProgram(std::string name) override;

    OutputList getOutputDescriptors() const override;
    bool initialise(size_t channels, size_t step_size, size_t block_size) override;
    void reset() override;
    FeatureSet process(const float* const* input_buffers, Vamp::RealTime timestamp) override;
    FeatureSet getRemainingFeatures() override;

  private:
    static constexpr size_t kMaxChannels = 64;
    void start();  // a new engine for the settings, prepared
    void add_row(const AnalysisRows::Row& row);
    void add_onset(const DecidedOnset& onset);

    Settings settings_;
    std::string program_;
    size_t channels_ = 0, block_size_ = 0;
    std::unique_ptr<Engine> engine_;
    std::unique_ptr<AnalysisRows> rows_;
    std::vector<float> vibration_;
    FeatureSet pending_;  // features of the rows completed in the current call
};

}  // namespace tactus::vamp
