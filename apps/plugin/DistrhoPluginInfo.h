// What DPF needs to know about the tactus plugin at compile time: names, ids, ports and the
// features it uses (state, programs, latency). One source builds LV2, VST3, CLAP and the JACK
// standalone (apps/plugin/CMakeLists.txt).
#pragma once

#define DISTRHO_PLUGIN_NAME "tactus"
#define DISTRHO_PLUGIN_URI "urn:tactus:vibrotactile"
#define DISTRHO_PLUGIN_CLAP_ID "org.tactus.vibrotactile"

#define DISTRHO_PLUGIN_HAS_UI 0
#define DISTRHO_PLUGIN_IS_RT_SAFE 1
#define DISTRHO_PLUGIN_IS_SYNTH 0
// Music in (stereo, downmixed by the engine); vibration out on every actuator channel, then
// the music passed through, delayed by the latency.
#define DISTRHO_PLUGIN_NUM_INPUTS 2
#define DISTRHO_PLUGIN_NUM_OUTPUTS 4
#define DISTRHO_PLUGIN_WANT_LATENCY 1
#define DISTRHO_PLUGIN_WANT_PROGRAMS 1
#define DISTRHO_PLUGIN_WANT_STATE 1
#define DISTRHO_PLUGIN_WANT_FULL_STATE 1
#define DISTRHO_PLUGIN_WANT_TIMEPOS 0

#define DISTRHO_PLUGIN_LV2_CATEGORY "lv2:AnalyserPlugin"
#define DISTRHO_PLUGIN_VST3_CATEGORIES "Fx|Analyzer"
#define DISTRHO_PLUGIN_CLAP_FEATURES "audio-effect", "analyzer", "stereo"
