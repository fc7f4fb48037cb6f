// The audio transport: the song's AudioContext, play / pause / seek, and the clock that every
// frame's time comes from (docs/design.md#rendering: time from the audio clock, never from frame counts).

/** What the render loop needs of a clock. */
export interface Clock {
  readonly playing: boolean;
  /** The song time now (s). Reads the clock only: no side effects. */
  now(): number;
  /** Whether playback has reached the end of the song (the loop then calls `rewind`). */
  ended(): boolean;
  /** Stop and go back to the start. */
  rewind(): void;
}

export class AudioTransport implements Clock {
  /** The song's length (s), from its spectrogram, so audio and motion end together. */
  duration = 0;
  /** At the song's end, play it again from the start (the *loop* switch, L). */
  loop = false;
  /** Called when playback starts or stops (to show ▶ or ❚❚). */
  onChange: (playing: boolean) => void = () => {};
  /** Called when the song stopped at its end (not looping): the page says so. */
  onEnd: () => void = () => {};

  private context: AudioContext | null = null;
  /** what plays, at full level: the recorder taps it */
  private mix: GainNode | null = null;
  /** `mix` at the listener's volume, to the speakers */
  private output: GainNode | null = null;
  private buffer: AudioBuffer | null = null;
  private source: AudioBufferSourceNode | null = null;
  /** context time at which song time 0 would have played */
  private startedAt = 0;
  /** song time while paused */
  private offset = 0;
  private isPlaying = false;
  private loudness = 1;
  private silenced = false;
  /** a live input's clock while one plays (docs/design.md#live): time, playing and the end
   * come from it, and the speakers stay silent (no feedback into a microphone) */
  private live: Clock | null = null;

  /** `createContext` is replaceable so tests can drive a fake clock. */
  constructor(private readonly createContext: () => AudioContext = () => new AudioContext()) {}

  get playing(): boolean { return this.live ? this.live.playing : this.isPlaying; }

  /** Whether a live input drives the clock. */
  get following(): boolean { return this.live !== null; }

  /** Let a live input's clock drive the motion (null: the song's again, paused). */
  follow(clock: Clock | null): void {
    this.pause();
    this.live = clock;
    this.applyVolume();
    this.onChange(this.playing);
  }

  /** The AudioContext (made on first use): live input runs in it, on the same clock. */
  get audioContext(): AudioContext { return this.audio(); }

  /** The node whatever plays goes into (at full level): `record` hears what reaches it, so
   * a live input connects here too. */
  get input(): AudioNode {
    this.audio();
    return this.mix!;
  }

  /** Playback volume in [0, 1] (the sound only: the motion follows the song, not the volume). */
  get volume(): number { return this.loudness; }
  set volume(value: number) {
    this.loudness = Math.max(0, Math.min(1, value));
    this.applyVolume();
  }

  get muted(): boolean { return this.silenced; }
  set muted(value: boolean) {
    this.silenced = value;
    this.applyVolume();
  }

  now(): number {
    if (this.live) return this.live.now();
    const t = this.isPlaying && this.context ? this.context.currentTime - this.startedAt
      : this.offset;
    return Math.min(t, this.duration);
  }

  ended(): boolean {
    if (this.live) return false;
    return this.isPlaying && this.context !== null
      && this.context.currentTime - this.startedAt >= this.duration;
  }

  /** Decode and keep a song's audio (`bytes`), or with null only its length (`?render` mode
   * plays no sound). A new song starts at 0:00. Throws when the browser cannot decode it. */
  async load(bytes: ArrayBuffer | null, duration: number): Promise<void> {
    this.pause();
    this.buffer = null;
    this.duration = duration;
    this.offset = 0;
    if (bytes === null) return;
    this.buffer = await this.audio().decodeAudioData(bytes);
  }

  play(): void {
    if (this.live) { void this.audio().resume(); return; } // a live input plays by itself
    if (this.isPlaying || !this.buffer) return;
    const context = this.audio();
    void context.resume();
    const source = context.createBufferSource();
    source.buffer = this.buffer;
    source.connect(this.mix!);
    source.start(0, this.offset);
    this.source = source;
    this.startedAt = context.currentTime - this.offset;
    this.isPlaying = true;
    this.onChange(true);
  }

  pause(): void {
    if (!this.isPlaying) return;
    this.offset = this.now();
    this.isPlaying = false;
    try { this.source?.stop(); } catch { /* already stopped */ }
    this.source = null;
    this.onChange(false);
  }

  seek(t: number): void {
    if (this.live) return;
    const wasPlaying = this.isPlaying;
    this.pause();
    this.offset = Math.max(0, Math.min(t, this.duration));
    if (wasPlaying) this.play();
  }

  rewind(): void {
    if (this.live) return;
    this.pause();
    this.offset = 0;
    if (this.loop) this.play(); // the *loop* switch: again from the start
    else this.onEnd();
  }

  /** A stream of what plays (at full level, whatever the volume), for the recorder; `untap`
   * it when done. */
  tap(): MediaStreamAudioDestinationNode {
    const destination = this.audio().createMediaStreamDestination();
    this.mix!.connect(destination);
    return destination;
  }

  untap(destination: MediaStreamAudioDestinationNode): void {
    this.mix?.disconnect(destination);
  }

  /** The AudioContext, made on first use (browsers want a page gesture before it sounds). */
  private audio(): AudioContext {
    if (!this.context) {
      this.context = this.createContext();
      this.mix = this.context.createGain();
      this.output = this.context.createGain();
      this.mix.connect(this.output);
      this.output.connect(this.context.destination);
      this.applyVolume();
    }
    return this.context;
  }

  private applyVolume(): void {
    if (this.output) this.output.gain.value = this.silenced || this.live ? 0 : this.loudness;
  }
}
