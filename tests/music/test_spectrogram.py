import av
import numpy as np
import pytest
import soundfile

import eigendance.music.analyser as stream
import eigendance.music.decode as decode
import eigendance.music.spectrogram as audio
from eigendance.cli import main
from eigendance.errors import EigendanceError
from eigendance.music.decode import read_audio
from eigendance.music.demo_music import demo_track, write_demo_wav
from eigendance.music.rhythm import FILE_KEYS, OPTIONAL_KEYS
from eigendance.music.spectrogram import Spectrogram, window_length
from helpers import fixture_path

SR = 44100


def tone(frequency, seconds=1.0, sample_rate=SR, amplitude=1.0):
    t = np.arange(int(seconds * sample_rate)) / sample_rate
    return amplitude * np.sin(2 * np.pi * frequency * t)


def band_of(spectrogram, frequency):
    return int(np.searchsorted(spectrogram.band_edges, frequency, side="right") - 1)


def pcm16(samples):
    return np.round(np.clip(samples, -1, 1) * 32767).astype(np.int16)


def test_hann_is_scipy_periodic_hann():
    from scipy.signal import get_window

    np.testing.assert_allclose(stream.hann(2048), get_window("hann", 2048), atol=1e-15)


def test_exponential_smoothing_matches_recursion_for_any_memory():
    values = np.random.default_rng(2).uniform(0, 1, (3000, 2))
    for memory in (0.0, 1e-40, 0.3, 0.88, 0.999):
        expected, state = np.empty_like(values), np.array([0.5, 0.2])
        for j, v in enumerate(values):
            state = memory * state + (1 - memory) * v
            expected[j] = state
        np.testing.assert_allclose(stream.exponential_smoothing(values, memory, [0.5, 0.2]),
                                   expected, rtol=1e-9, atol=1e-12)


def test_window_length():
    assert window_length(44100) == 2048
    # 0.046·48000 = 2208 → 4096 (docs/design.md#spectrogram).
    assert window_length(48000) == 4096
    assert window_length(192000) == 16384
    assert window_length(8000) == 512


@pytest.mark.parametrize("frequency", [250.0, 440.0, 1000.0, 5000.0, 12000.0])
def test_pure_tone_peaks_in_its_band_at_full_scale(frequency):
    spectrogram = Spectrogram.from_samples(tone(frequency), SR, smoothing=0)
    middle = spectrogram.values[len(spectrogram.values) // 2]
    assert middle.argmax() == band_of(spectrogram, frequency)
    assert middle.max() == pytest.approx(1.0, abs=0.02)  # scalloping ≤ 1.42 dB = 0.018


def test_half_scale_tone_reads_minus_six_decibels():
    spectrogram = Spectrogram.from_samples(tone(1000.0, amplitude=0.5), SR, smoothing=0)
    middle = spectrogram.values[50]
    assert middle.max() == pytest.approx(1 - 20 * np.log10(2) / 80, abs=0.02)


def test_silence_is_zero_and_frame_count():
    spectrogram = Spectrogram.from_samples(np.zeros(SR), SR)
    assert spectrogram.values.shape == (101, 64)
    assert not spectrogram.values.any()
    np.testing.assert_allclose(spectrogram.times, np.arange(101) / 100)
    assert spectrogram.duration == 1.0


def test_values_in_unit_interval_and_float32():
    noise = np.random.default_rng(3).uniform(-1, 1, SR // 2) * 4  # clipping, loud
    spectrogram = Spectrogram.from_samples(noise, SR)
    assert spectrogram.values.dtype == np.float32
    assert spectrogram.values.min() >= 0 and spectrogram.values.max() <= 1


def test_band_edges_and_empty_bands():
    spectrogram = Spectrogram.from_samples(np.zeros(100), 22050, bands=32)
    assert spectrogram.band_edges[0] == pytest.approx(20)
    assert spectrogram.band_edges[-1] == pytest.approx(11025)  # min(16 kHz, sr/2)
    np.testing.assert_allclose(spectrogram.band_centres,
                               np.sqrt(spectrogram.band_edges[:-1] * spectrogram.band_edges[1:]))
    # A 100 Hz tone: its low band holds no FFT bin and takes the interpolated spectrum, near 1.
    spectrogram = Spectrogram.from_samples(tone(100.0), SR, smoothing=0)
    assert spectrogram.values[50, band_of(spectrogram, 100.0)] > 0.95


def test_smoothing_step_response_has_time_constant_tau():
    tau, rate = 0.08, 100
    signal = np.concatenate([np.zeros(SR // 2), tone(1000.0)])
    raw = Spectrogram.from_samples(signal, SR, rate=rate, smoothing=0).values.astype(np.float64)
    smooth = Spectrogram.from_samples(signal, SR, rate=rate, smoothing=tau).values
    memory = np.exp(-1 / (rate * tau))
    expected = np.zeros_like(raw)
    state = np.zeros(raw.shape[1])
    for j, v in enumerate(raw):  # the recursion of docs/design.md#spectrogram, frame by frame
        state = memory * state + (1 - memory) * v
        expected[j] = state
    np.testing.assert_allclose(smooth, expected, atol=1e-6)
    # Step from 0 to ≈1: after τ the response reaches 1 − 1/e of the way.
    band = band_of(raw_spec := Spectrogram.from_samples(tone(1000.0), SR, smoothing=tau), 1000)
    response = raw_spec.values[:, band]
    assert response[int(rate * tau) - 1] == pytest.approx(1 - np.exp(-1), abs=0.03)
    assert response[int(5 * rate * tau)] == pytest.approx(1.0, abs=0.03)


def test_chunked_analysis_matches_one_chunk(monkeypatch):
    samples, sr = demo_track(2.0)
    whole = Spectrogram.from_samples(samples, sr)
    monkeypatch.setattr(audio, "CHUNK_SAMPLES", 777)
    monkeypatch.setattr(stream, "FRAME_BATCH", 5)
    chunked = Spectrogram.from_samples(samples, sr)
    np.testing.assert_array_equal(whole.values, chunked.values)


def test_streaming_buffer_stays_bounded():
    analyser = stream.Analyser(SR)
    rng = np.random.default_rng(0)
    largest = 0
    for _ in range(40):  # 40 chunks of 0.25 s: the buffer holds one chunk and a window at most
        analyser.feed(rng.uniform(-1, 1, SR // 4))
        largest = max(largest, len(analyser.buffer))
    assert largest <= SR // 4 + analyser.N
    assert len(analyser.finish()) == 1001


def test_frame_centres_round_half_up():
    # 22050/100 = 220.5 samples per frame: c_1 = 221, c_3 = 662 (not banker's rounding).
    np.testing.assert_array_equal(stream.frame_centres(0, 4, 22050, 100), [0, 221, 441, 662])


def test_at_interpolates_linearly_and_clamps():
    spectrogram = Spectrogram.from_samples(tone(440.0, 0.5), SR)
    values = spectrogram.values.astype(np.float64)
    np.testing.assert_allclose(spectrogram.at([0.03]), values[[3]])
    np.testing.assert_allclose(spectrogram.at(0.125), 0.5 * (values[12] + values[13]))
    np.testing.assert_allclose(spectrogram.at([-1.0, 99.0]), values[[0, -1]])


def test_save_load_round_trip(tmp_path):
    spectrogram = Spectrogram.from_samples(tone(440.0, 0.3), SR, rate=50, bands=16)
    spectrogram.save(tmp_path / "s.npz")
    loaded = Spectrogram.load(tmp_path / "s.npz")
    np.testing.assert_array_equal(loaded.values, spectrogram.values)
    np.testing.assert_array_equal(loaded.band_edges, spectrogram.band_edges)
    assert (loaded.rate, loaded.sample_rate, loaded.duration) == (50.0, SR, spectrogram.duration)
    with np.load(tmp_path / "s.npz") as data:
        assert set(data.files) == {*audio.FORMAT_KEYS, "version", *FILE_KEYS, *OPTIONAL_KEYS}
        assert data["values"].dtype == np.float32


def test_wav_and_flac_identical_mp3_close(tmp_path):
    samples, sr = demo_track(4.0)
    stereo = pcm16(np.stack([samples, 0.5 * samples[::-1]], axis=1))
    for suffix in ("wav", "flac"):
        soundfile.write(tmp_path / f"music.{suffix}", stereo, sr)
    soundfile.write(tmp_path / "music.mp3", stereo / 32768.0, sr)  # libsndfile's LAME
    wav = Spectrogram.from_file(tmp_path / "music.wav")
    flac = Spectrogram.from_file(tmp_path / "music.flac")
    mp3 = Spectrogram.from_file(tmp_path / "music.mp3")
    np.testing.assert_allclose(flac.values, wav.values, atol=1e-6)
    assert mp3.values.shape == wav.values.shape
    difference = np.abs(mp3.values - wav.values)
    # Measured on the demo music at libsndfile's default MP3 quality: mean 0.002, 99th
    # percentile 0.02, max 0.05 (on the 0–1 loudness scale, i.e. about 4 dB at the worst bin).
    assert difference.mean() < 0.01
    assert np.percentile(difference, 99) < 0.05
    assert difference.max() < 0.15


@pytest.mark.parametrize("channels", [1, 2, 8])
def test_channels_mix_by_mean(tmp_path, channels):
    rng = np.random.default_rng(channels)
    data = pcm16(rng.uniform(-0.5, 0.5, (SR // 4, channels)) * np.arange(1, channels + 1) / 8)
    soundfile.write(tmp_path / "multi.wav", data, SR)
    samples, sample_rate = read_audio(tmp_path / "multi.wav")
    assert sample_rate == SR
    np.testing.assert_allclose(samples, data.mean(axis=1) / 32768, atol=1e-7)
    from_file = Spectrogram.from_file(tmp_path / "multi.wav")
    from_samples = Spectrogram.from_samples(data / 32768.0, SR)
    np.testing.assert_allclose(from_file.values, from_samples.values, atol=1e-6)


def test_pyav_stereo_is_averaged_not_summed(tmp_path):
    # Left: a full-scale 1 kHz tone, right: silence. The mean is a half-scale tone (−6 dB).
    path = tmp_path / "left.m4a"
    t = np.arange(SR) / SR
    left = np.sin(2 * np.pi * 1000 * t).astype(np.float32)
    with av.open(str(path), "w") as container:
        stream = container.add_stream("aac", rate=SR, layout="stereo")
        frame = av.AudioFrame.from_ndarray(np.stack([left, np.zeros_like(left)]), format="fltp",
                                           layout="stereo")
        frame.sample_rate = SR
        for packet in stream.encode(frame):
            container.mux(packet)
        for packet in stream.encode(None):
            container.mux(packet)
    samples, sample_rate = read_audio(path)
    assert sample_rate == SR
    middle = samples[SR // 4: SR // 2]
    # Mean: RMS 0.354 (AAC loses ≈5%); PyAV's mono resampler would give 0.5.
    assert np.sqrt(np.mean(middle ** 2)) == pytest.approx(0.5 / np.sqrt(2), rel=0.1)


@pytest.mark.parametrize("channels, subtype", [(2, "PCM_16"), (8, "PCM_24"), (3, "FLOAT")])
def test_pyav_decodes_the_same_pcm_as_soundfile(tmp_path, channels, subtype):
    data = np.random.default_rng(1).uniform(-0.9, 0.9, (5000, channels))
    path = tmp_path / "a.wav"
    soundfile.write(path, data, SR, subtype=subtype)
    _, chunks = decode._open_pyav(str(path))
    via_pyav = np.concatenate(list(chunks))
    via_soundfile, _ = read_audio(path)
    np.testing.assert_allclose(via_pyav, via_soundfile, atol=1e-7)
    np.testing.assert_allclose(via_pyav, data.mean(axis=1), atol=1e-4)


def test_opus_through_pyav(tmp_path):
    path = tmp_path / "tone.opus"
    rate = 48000
    t = np.arange(rate) / rate
    wave = (0.5 * np.sin(2 * np.pi * 1000 * t)).astype(np.float32)
    with av.open(str(path), "w", format="ogg") as container:
        stream = container.add_stream("libopus", rate=rate, layout="mono")
        for start in range(0, rate, 960):
            frame = av.AudioFrame.from_ndarray(wave[None, start:start + 960], format="flt",
                                               layout="mono")
            frame.sample_rate = rate
            frame.pts = start
            for packet in stream.encode(frame):
                container.mux(packet)
        for packet in stream.encode(None):
            container.mux(packet)
    spectrogram = Spectrogram.from_file(path)
    assert spectrogram.sample_rate == rate
    assert spectrogram.values[50].argmax() == band_of(spectrogram, 1000)


def test_integer_pcm_samples_are_scaled():
    wave = tone(1000.0, 0.3)
    as_int = Spectrogram.from_samples(pcm16(wave), SR).values
    np.testing.assert_allclose(as_int, Spectrogram.from_samples(wave, SR).values, atol=1e-3)


def test_one_sample_and_empty_audio(tmp_path):
    soundfile.write(tmp_path / "one.wav", np.array([0.5]), SR)
    spectrogram = Spectrogram.from_file(tmp_path / "one.wav")
    assert spectrogram.values.shape == (1, 64)
    assert 0 <= spectrogram.values.min() <= spectrogram.values.max() <= 1
    soundfile.write(tmp_path / "none.wav", np.zeros(0), SR)
    with pytest.raises(EigendanceError, match="none.wav: holds no audio samples"):
        Spectrogram.from_file(tmp_path / "none.wav")
    with pytest.raises(EigendanceError, match="no audio samples"):
        Spectrogram.from_samples(np.zeros(0), SR)


def one_line_error(call):
    with pytest.raises(EigendanceError) as caught:
        call()
    assert "\n" not in str(caught.value)
    return str(caught.value)


def test_broken_files_give_one_line_errors(tmp_path):
    assert "no such file" in one_line_error(lambda: Spectrogram.from_file(tmp_path / "x.wav"))
    (tmp_path / "empty.mp3").write_bytes(b"")
    assert "empty" in one_line_error(lambda: Spectrogram.from_file(tmp_path / "empty.mp3"))
    (tmp_path / "noise.wav").write_bytes(np.random.default_rng(0).bytes(5000))
    one_line_error(lambda: Spectrogram.from_file(tmp_path / "noise.wav"))
    (tmp_path / "text.m4a").write_text("not audio at all")
    one_line_error(lambda: Spectrogram.from_file(tmp_path / "text.m4a"))


def test_truncated_files_decode_what_is_there(tmp_path):
    samples, sr = demo_track(2.0)
    for suffix in ("wav", "flac", "ogg", "mp3"):
        path = tmp_path / f"whole.{suffix}"
        soundfile.write(path, samples, sr)
        cut = tmp_path / f"cut.{suffix}"
        cut.write_bytes(path.read_bytes()[: path.stat().st_size // 2])
        try:
            spectrogram = Spectrogram.from_file(cut)
        except EigendanceError as error:  # acceptable: one line
            assert "\n" not in str(error)
            continue
        assert 0 < spectrogram.duration <= 2.0 + 0.1
        assert spectrogram.values.min() >= 0 and spectrogram.values.max() <= 1


def test_bad_parameters_give_one_line_errors():
    one_line_error(lambda: Spectrogram.from_samples(np.zeros(10), SR, rate=0))
    one_line_error(lambda: Spectrogram.from_samples(np.zeros(10), SR, bands=0))
    one_line_error(lambda: Spectrogram.from_samples(np.zeros(10), 30))  # sr/2 below 20 Hz
    one_line_error(lambda: Spectrogram.from_samples(np.array([np.nan]), SR))
    one_line_error(lambda: Spectrogram.from_samples(np.zeros((2, 2, 2)), SR))


def test_real_music_fixtures():
    for name in ("sorohanro_solo_trumpet_06.ogg", "kevin_macleod_vibe_ace_20s-24s.ogg"):
        spectrogram = Spectrogram.from_file(fixture_path("audio", name))
        assert spectrogram.sample_rate == SR
        assert spectrogram.values.shape[1] == 64
        assert len(spectrogram.times) == int(spectrogram.duration * 100) + 1
        assert 0.02 < spectrogram.values.mean() < 0.9


def test_demo_music_is_deterministic_and_spans_the_bands(tmp_path):
    first, sr = demo_track(4.0)
    second, _ = demo_track(4.0)
    np.testing.assert_array_equal(first, second)
    assert sr == SR and np.abs(first).max() == pytest.approx(0.9)
    spectrogram = Spectrogram.from_samples(first, sr)
    loudest = spectrogram.values.max(axis=0)
    assert (loudest[:8] > 0.6).all() and (loudest[-8:] > 0.2).all()  # bass and hi-hats
    # A clear beat: the low bands pulse twice a second (120 bpm).
    low = spectrogram.values[:, :6].mean(axis=1) - spectrogram.values[:, :6].mean()
    spectrum = np.abs(np.fft.rfft(low))
    frequencies = np.fft.rfftfreq(len(low), 1 / spectrogram.rate)
    assert frequencies[spectrum[1:].argmax() + 1] == pytest.approx(2.0, abs=0.3)
    write_demo_wav(tmp_path / "demo.wav", 1.0)
    assert soundfile.info(str(tmp_path / "demo.wav")).frames == SR


def test_cli_spectrum(tmp_path, capsys):
    write_demo_wav(tmp_path / "demo.wav", 2.0)
    out = tmp_path / "s.npz"
    assert main(["spectrum", str(tmp_path / "demo.wav"), "--bands", "32", "--rate", "50",
                 "-o", str(out), "--png", str(tmp_path / "s.png")]) == 0
    loaded = Spectrogram.load(out)
    assert loaded.values.shape == (101, 32)
    assert (tmp_path / "s.png").read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
    assert main(["spectrum", str(tmp_path / "demo.wav"), "-o", str(out)]) == 1
    assert "exists" in capsys.readouterr().err
    assert main(["spectrum", str(tmp_path / "missing.wav"), "-o", str(tmp_path / "t.npz")]) == 1


def test_smoothed_runs_the_recursion_once_more_over_the_frames():
    samples, rate = demo_track(1.0)
    spectrogram = Spectrogram.from_samples(samples, rate, bands=8)
    tau = 0.2
    smoothed = spectrogram.smoothed(tau)
    memory = np.exp(-1 / (spectrogram.rate * tau))
    state = np.zeros(8)
    for j, row in enumerate(spectrogram.values):  # the player's smoothing, frame by frame
        state = memory * state + (1 - memory) * row
        np.testing.assert_allclose(smoothed.values[j], state, rtol=1e-5, atol=1e-6)
    assert spectrogram.smoothed(0.0) is spectrogram
