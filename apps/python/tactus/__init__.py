"""tactus: music to vibrotactile feedback, on numpy arrays.

The library the `tactus` command line runs, with the same values bit for bit:

    y = tactus.render(x, sample_rate)                  # `tactus render`
    columns = tactus.analyze(x, sample_rate)           # `tactus analyze`
    onsets = tactus.onsets(x, sample_rate)             # `tactus onsets`
    levels = tactus.meter(y, sample_rate)              # `tactus meter -o`
    engine = tactus.Engine(sample_rate)                # block by block, live parameters
    y = tactus.stream_file(engine, "in.wav")           # an engine over a file, or over
    y = tactus.stream_buffer(engine, x)                #   an array: the command line's loop
    tactus.threshold_db("P", f, contact_area_cm2=0.5)  # the perception model

Parameters (tactus.params()) are named by their key in a `settings` dict
(settings={"envelope.decay_ms": 120}) or by their Python name, the key with its dots as
underscores, as keyword arguments and Engine attributes (envelope_decay_ms=120).
"""

from ._tactus import (Engine, __version__, analyze, channels, combined_sensation_db,
                      detecting_channel, detection_threshold_db, drum_parts, meter, onsets, params,
                      presets, read, render, sensation_level_db, stream_buffer, stream_file,
                      threshold_db, write)

__all__ = ["Engine", "analyze", "channels", "combined_sensation_db", "detecting_channel",
           "detection_threshold_db", "drum_parts", "meter", "onsets", "params", "presets", "read",
           "render", "sensation_level_db", "stream_buffer", "stream_file", "threshold_db", "write",
           "__version__"]
