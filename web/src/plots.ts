// The small 2D plots: the live spectrum strip, and under each tile its transfer (which harmonic
// each sound band drives) and its amplification (how strongly each harmonic moves the model).
import type { Spectrum } from "./bundle";
import { hasBeats } from "./beat-lock";
import { kickAt } from "./filter";
import type { Prepared } from "./filter";

/** How long a beat tick on the spectrum strip takes to fade, s. */
const TICK_DECAY = 0.12;
const tick = (amount: number) => ({ amount, decay: TICK_DECAY, source: "beats" as const,
  routed: new Float64Array(0), targets: new Int32Array(0) });
/** A beat ticks at half strength, a bar's first beat (a downbeat) at full strength. */
const BEAT = tick(0.5), DOWNBEAT = tick(1);

/** The rhythm on the spectrum strip: its top edge lights up on each of the song's beats, twice
 * as bright on each downbeat, and fades in TICK_DECAY (CSS variable --beat, the opacity of
 * #spectrum::after); a mark along its bottom edge per section start (at start/duration of the
 * width, `drawSections`); the strip's title says the tempo, the meter and the sections. */
export function drawBeat(strip: HTMLElement, spectrum: Spectrum | null, t: number): void {
  const beats = spectrum && hasBeats(spectrum) ? spectrum.beats : null;
  const bars = beats && spectrum!.meter > 0 ? spectrum!.downbeats : null;
  const kick = beats ? Math.max(kickAt(BEAT, beats, t), bars ? kickAt(DOWNBEAT, bars, t) : 0) : 0;
  strip.style.setProperty("--beat", kick.toFixed(3));
  const meter = bars ? ` in ${spectrum!.meter}/4, brighter on each bar's first beat` : "";
  const parts = spectrum?.sections.length
    ? `; ${spectrum.sections.length + 1} sections (a mark along the bottom edge where each starts)`
    : "";
  const tempo = beats ? `${spectrum!.tempo.toFixed(0)} BPM${meter}: the top edge ticks on each beat${parts}`
    : "no beat detected: the dance follows the loudness";
  if (strip.dataset.tempo !== tempo) {
    strip.dataset.tempo = tempo;
    strip.title = `the song's loudness per band now: bass on the left, treble on the right; ${tempo}`;
  }
  drawSections(strip, spectrum);
}

/** One `i.section` mark per section start of the song, at start/duration of the strip's width
 * (remade only when the song changes). */
function drawSections(strip: HTMLElement, spectrum: Spectrum | null): void {
  const starts = spectrum?.sections ?? new Float32Array(0);
  const key = spectrum ? `${spectrum.name} ${spectrum.duration} ${starts.join(",")}` : "";
  if (strip.dataset.sections === key) return;
  strip.dataset.sections = key;
  strip.querySelectorAll(":scope > i.section").forEach((mark) => mark.remove());
  starts.forEach((start) => {
    const mark = document.createElement("i");
    mark.className = "section";
    mark.style.left = `${((100 * start) / spectrum!.duration).toFixed(3)}%`;
    mark.dataset.start = start.toFixed(2);
    strip.append(mark);
  });
}

const DRIVEN = "#ffb347";
const IDLE = "#5a6070";

/** The live spectrum strip: one bar per band, height and brightness by its value in [0, 1].
 * Bars are elements, not a 2D canvas: a 2D canvas redrawn every frame made headless Chromium's
 * compositor drop a band of the WebGL canvas (at the strip's rectangle, upside down). */
export function drawSpectrum(strip: HTMLElement, bandValues: Float32Array): void {
  const B = bandValues.length;
  const bars = strip.getElementsByTagName("span");
  if (bars.length !== B) {
    for (const bar of [...bars]) bar.remove();
    strip.prepend(...Array.from({ length: B }, (_, b) => {
      const bar = document.createElement("span");
      bar.style.background = `hsl(${30 + 200 * (b / B)}, 80%, 55%)`;
      return bar;
    }));
  }
  for (let b = 0; b < B; b++) {
    const v = Math.max(0, Math.min(1, bandValues[b]));
    bars[b].style.transform = `scaleY(${v.toFixed(3)})`;
    bars[b].style.opacity = (0.45 + 0.55 * v).toFixed(3);
  }
}

/** The transfer as dots: sound band (x, low to high pitch) → harmonic it drives (y, low to high
 * frequency of the shape). */
export function drawTransfer(canvas: HTMLCanvasElement, prepared: Prepared): void {
  const t = canvas.getContext("2d")!;
  const { width, height } = canvas;
  t.clearRect(0, 0, width, height);
  t.fillStyle = "#ffffff14";
  t.fillRect(0, 0, width, height);
  const B = prepared.harmonicOfBand.length;
  t.fillStyle = DRIVEN;
  prepared.harmonicOfBand.forEach((v, b) => {
    const x = ((b + 0.5) / B) * width;
    const y = height - 2 - ((v + 0.5) / prepared.k) * (height - 4);
    t.fillRect(x - 1, y - 1, 2.5, 2.5);
  });
}

/** How strongly a mapping moves each harmonic ν per unit of loudness: a(ν)·|X̃_ν| (the
 * amplification times the harmonic's share of the shape), signed. */
export function effectiveAmplification(prepared: Prepared, coefficients: Float32Array):
    Float64Array {
  const out = new Float64Array(prepared.k);
  for (let v = 0; v < prepared.k; v++) {
    const c = Math.hypot(coefficients[3 * v], coefficients[3 * v + 1], coefficients[3 * v + 2]);
    out[v] = prepared.gain * prepared.amplification[v] * c;
  }
  return out;
}

/** The effective amplification as bars about a zero line (up: the shape's feature grows with
 * the music, down: it shrinks or turns over), harmonics along x from low to high, scaled to the
 * tile's largest bar; the harmonics the music reaches in colour, the others grey. */
export function drawAmplification(canvas: HTMLCanvasElement, prepared: Prepared,
                                  effective: Float64Array): void {
  const a = canvas.getContext("2d")!;
  const { width, height } = canvas;
  a.clearRect(0, 0, width, height);
  a.fillStyle = "#ffffff14";
  a.fillRect(0, 0, width, height);
  a.fillStyle = "#444b58";
  a.fillRect(0, height / 2, width, 1);
  const reached = new Set(prepared.harmonicOfBand);
  const k = prepared.k;
  let largest = 0;
  for (let v = 0; v < k; v++) largest = Math.max(largest, Math.abs(effective[v]));
  for (let v = 0; v < k; v++) {
    const h = Math.max(-1, Math.min(1, effective[v] / (largest || 1))) * (height / 2 - 1);
    if (!h) continue;
    a.fillStyle = reached.has(v) ? DRIVEN : IDLE;
    const x = Math.floor((v / k) * width);
    a.fillRect(x, height / 2 - Math.max(h, 0), Math.max(1, Math.ceil(width / k)),
      Math.max(1, Math.abs(h)));
  }
}
