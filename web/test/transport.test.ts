// The audio transport on a fake AudioContext: now() only reads the clock; the end of the song
// is seen by ended() and handled by rewind().
import { describe, expect, it } from "vitest";
import { AudioTransport } from "../src/transport";

/** Just enough of an AudioContext, with a clock the test moves. */
class FakeContext {
  currentTime = 100;
  destination = {};
  gains: { gain: { value: number } }[] = [];
  createGain() {
    const node = { gain: { value: 1 }, connect() {}, disconnect() {} };
    this.gains.push(node);
    return node;
  }
  createBufferSource() {
    return { buffer: null, connect() {}, start() {}, stop() {} };
  }
  async decodeAudioData(bytes: ArrayBuffer) { return { duration: bytes.byteLength }; }
  async resume() {}
}

async function loaded(): Promise<{ transport: AudioTransport; context: FakeContext }> {
  const context = new FakeContext();
  const transport = new AudioTransport(() => context as unknown as AudioContext);
  await transport.load(new ArrayBuffer(8), 8);
  return { transport, context };
}

describe("AudioTransport", () => {
  it("follows the audio clock while playing and holds still while paused", async () => {
    const { transport, context } = await loaded();
    const changes: boolean[] = [];
    transport.onChange = (playing) => changes.push(playing);
    transport.play();
    context.currentTime += 1.5;
    expect(transport.now()).toBeCloseTo(1.5);
    transport.pause();
    context.currentTime += 3;
    expect(transport.now()).toBeCloseTo(1.5);
    transport.seek(6);
    expect(transport.now()).toBe(6);
    expect(changes).toEqual([true, false]);
  });

  it("now() has no side effects at the end of the song; rewind() stops and goes to 0", async () => {
    const { transport, context } = await loaded();
    transport.seek(7);
    transport.play();
    context.currentTime += 2;
    expect(transport.ended()).toBe(true);
    for (let i = 0; i < 3; i++) expect(transport.now()).toBe(8); // clamped, still playing
    expect(transport.playing).toBe(true);
    let ends = 0;
    transport.onEnd = () => { ends += 1; };
    transport.rewind();
    expect(transport.playing).toBe(false);
    expect(transport.ended()).toBe(false);
    expect(transport.now()).toBe(0);
    expect(ends).toBe(1); // the page says the song ended
    transport.loop = true;
    transport.play();
    context.currentTime += 9;
    transport.rewind(); // looping: it plays on from the start, no end to say
    expect(transport.playing).toBe(true);
    expect(ends).toBe(1);
  });

  it("plays nothing without audio (?render): the time starts at 0", async () => {
    const transport = new AudioTransport(() => { throw new Error("no AudioContext wanted"); });
    await transport.load(null, 5);
    transport.play();
    expect(transport.playing).toBe(false);
    expect(transport.now()).toBe(0);
    expect(transport.ended()).toBe(false);
  });

  it("a new song starts at 0:00, paused", async () => {
    const { transport, context } = await loaded();
    transport.seek(5);
    transport.play();
    context.currentTime += 1;
    await transport.load(new ArrayBuffer(4), 4);
    expect(transport.playing).toBe(false);
    expect(transport.now()).toBe(0);
  });

  it("volume and mute change the sound only, not the clock", async () => {
    const { transport, context } = await loaded();
    const [, speakers] = context.gains; // mix (full level, recorded), then the speakers
    transport.volume = 0.25;
    expect(speakers.gain.value).toBe(0.25);
    transport.muted = true;
    expect(speakers.gain.value).toBe(0);
    expect(context.gains[0].gain.value).toBe(1);
    transport.play();
    context.currentTime += 2;
    expect(transport.now()).toBeCloseTo(2);
    transport.muted = false;
    expect(speakers.gain.value).toBe(0.25);
    transport.volume = 7;
    expect(transport.volume).toBe(1);
  });
});
