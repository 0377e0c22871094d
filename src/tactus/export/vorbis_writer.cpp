#include "tactus/export/vorbis_writer.hpp"

#include <fmt/format.h>
#include <vorbis/vorbisenc.h>

#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>

#include "tactus/io/temporary_path.hpp"

namespace tactus {

struct VorbisEncoder::State {
    ogg_stream_state stream{};
    vorbis_info info{};
    vorbis_comment comment{};
    vorbis_dsp_state dsp{};
    vorbis_block block{};
};

VorbisEncoder::VorbisEncoder(double sample_rate_hz, int channels, const VorbisComments& comments,
                             float quality, Sink sink)
    : channels_(channels), sink_(std::move(sink)), state_(std::make_unique<State>()) {
    State& s = *state_;
    vorbis_info_init(&s.info);
    if (vorbis_encode_init_vbr(&s.info, channels, static_cast<long>(sample_rate_hz), quality) !=
        0) {
        vorbis_info_clear(&s.info);
        state_.reset();
        throw std::runtime_error(
            fmt::format("Vorbis cannot encode {} channels at {:g} Hz", channels, sample_rate_hz));
    }
    vorbis_comment_init(&s.comment);
    for (const auto& [tag, value] : comments)
        vorbis_comment_add_tag(&s.comment, tag.c_str(), value.c_str());
    vorbis_analysis_init(&s.dsp, &s.info);
    vorbis_block_init(&s.dsp, &s.block);
    ogg_stream_init(&s.stream, static_cast<int>(std::random_device{}() & 0x7fffffff));
    ogg_packet header, comment_header, codebooks;
    vorbis_analysis_headerout(&s.dsp, &s.comment, &header, &comment_header, &codebooks);
    ogg_stream_packetin(&s.stream, &header);
    ogg_stream_packetin(&s.stream, &comment_header);
    ogg_stream_packetin(&s.stream, &codebooks);
    // The headers end on a page of their own (the Vorbis spec asks audio to start on a new page).
    for (ogg_page page; ogg_stream_flush(&s.stream, &page) != 0;) {
        sink_(page.header, static_cast<size_t>(page.header_len));
        sink_(page.body, static_cast<size_t>(page.body_len));
    }
}

VorbisEncoder::~VorbisEncoder() {
    if (state_) {
        ogg_stream_clear(&state_->stream);
        vorbis_block_clear(&state_->block);
        vorbis_dsp_clear(&state_->dsp);
        vorbis_comment_clear(&state_->comment);
        vorbis_info_clear(&state_->info);
    }
}

void VorbisEncoder::flush_pages(bool all) {
    State& s = *state_;
    while (vorbis_analysis_blockout(&s.dsp, &s.block) == 1) {
        vorbis_analysis(&s.block, nullptr);
        vorbis_bitrate_addblock(&s.block);
        for (ogg_packet packet; vorbis_bitrate_flushpacket(&s.dsp, &packet) != 0;) {
            ogg_stream_packetin(&s.stream, &packet);
            for (ogg_page page; ogg_stream_pageout(&s.stream, &page) != 0;) {
                sink_(page.header, static_cast<size_t>(page.header_len));
                sink_(page.body, static_cast<size_t>(page.body_len));
            }
        }
    }
    if (all)
        for (ogg_page page; ogg_stream_flush(&s.stream, &page) != 0;) {
            sink_(page.header, static_cast<size_t>(page.header_len));
            sink_(page.body, static_cast<size_t>(page.body_len));
        }
}

void VorbisEncoder::write(const float* const* channels, int frames) {
    if (frames <= 0) return;
    float** buffer = vorbis_analysis_buffer(&state_->dsp, frames);
    for (int c = 0; c < channels_; ++c)
        std::memcpy(buffer[c], channels[c], sizeof(float) * static_cast<size_t>(frames));
    vorbis_analysis_wrote(&state_->dsp, frames);
    flush_pages(false);
}

void VorbisEncoder::finish() {
    vorbis_analysis_wrote(&state_->dsp, 0);  // end of stream
    flush_pages(true);
}

VorbisWriter::VorbisWriter(const std::filesystem::path& path, double sample_rate_hz, int channels,
                           const VorbisComments& comments)
    : path_(path), temporary_(temporary_path_for(path)) {
    const auto to_file = [this](const unsigned char* bytes, size_t count) {
        std::fwrite(bytes, 1, count, file_);
        if (std::ferror(file_))
            throw std::runtime_error(fmt::format("{}: write failed", path_.string()));
    };
    track_temporary(temporary_);
    file_ = std::fopen(temporary_.c_str(), "wb");
    if (!file_) {
        const std::string reason = std::strerror(errno);
        discard_temporary(temporary_);
        throw std::runtime_error(fmt::format("{}: cannot write: {}", path.string(), reason));
    }
    try {
        encoder_ =
            std::make_unique<VorbisEncoder>(sample_rate_hz, channels, comments, kQuality, to_file);
    } catch (const std::runtime_error& e) {
        std::fclose(file_);
        file_ = nullptr;
        discard_temporary(temporary_);
        throw std::runtime_error(fmt::format("{}: {}", path.string(), e.what()));
    }
}

VorbisWriter::~VorbisWriter() {
    encoder_.reset();
    if (file_) {
        std::fclose(file_);
        discard_temporary(temporary_);
    }
}

void VorbisWriter::write(const float* const* channels, int frames) {
    encoder_->write(channels, frames);
}

void VorbisWriter::commit() {
    encoder_->finish();
    const int error = std::fclose(file_);
    file_ = nullptr;
    if (error != 0) {
        discard_temporary(temporary_);
        throw std::runtime_error(fmt::format("{}: write failed", path_.string()));
    }
    commit_temporary(temporary_, path_);
}

std::string vorbis_file_bytes(const std::vector<float>& mono, double sample_rate_hz,
                              float quality) {
    std::string bytes;
    VorbisEncoder encoder(sample_rate_hz, 1, {}, quality,
                          [&](const unsigned char* data, size_t count) {
                              bytes.append(reinterpret_cast<const char*>(data), count);
                          });
    constexpr int kChunk = 4096;  // frames handed to the encoder at a time
    for (size_t at = 0; at < mono.size(); at += kChunk) {
        const float* channel = mono.data() + at;
        encoder.write(&channel, static_cast<int>(std::min<size_t>(kChunk, mono.size() - at)));
    }
    encoder.finish();
    return bytes;
}

}  // namespace tactus
