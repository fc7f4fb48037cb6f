// The small 2D plots: the live spectrum strip above the gallery, and each tile's transfer
// (band → harmonic) and amplification (per harmonic).
import type { Mapping } from "./filter";

const cssColor = (color: number) => `#${color.toString(16).padStart(6, "0")}`;

/** One bar per band, height and lightness by its value in [0, 1]. */
export function drawSpectrum(strip: HTMLCanvasElement, bandValues: Float32Array): void {
  const context = strip.getContext("2d")!;
  const { width, height } = strip;
  context.clearRect(0, 0, width, height);
  const B = bandValues.length;
  for (let b = 0; b < B; b++) {
    const v = bandValues[b];
    context.fillStyle = `hsl(${30 + 200 * (b / B)}, 80%, ${35 + 30 * v}%)`;
    const x0 = Math.floor((b / B) * width), x1 = Math.floor(((b + 1) / B) * width);
    context.fillRect(x0, height * (1 - v), Math.max(1, x1 - x0 - 1), height * v);
  }
}

/** The transfer as a line: band (x) → normalised harmonic (y). */
export function drawTransfer(canvas: HTMLCanvasElement, mapping: Mapping, color: number): void {
  const t = canvas.getContext("2d")!;
  const { width, height } = canvas;
  t.clearRect(0, 0, width, height);
  t.strokeStyle = cssColor(color);
  t.lineWidth = 1.5;
  t.beginPath();
  mapping.transfer.forEach((value, b) => {
    const x = (b / Math.max(1, mapping.transfer.length - 1)) * (width - 2) + 1;
    const y = height - 2 - value * (height - 4);
    if (b === 0) t.moveTo(x, y); else t.lineTo(x, y);
  });
  t.stroke();
}

/** The amplification as bars about a zero line, scaled by `largest` |a| of the generation so
 * tiles compare at a glance. */
export function drawAmplification(canvas: HTMLCanvasElement, mapping: Mapping, largest: number,
                                  color: number): void {
  const a = canvas.getContext("2d")!;
  const { width, height } = canvas;
  a.clearRect(0, 0, width, height);
  a.fillStyle = "#444";
  a.fillRect(0, height / 2, width, 1);
  a.fillStyle = cssColor(color);
  const K = mapping.amplification.length;
  mapping.amplification.forEach((value, v) => {
    const x = Math.floor((v / K) * width);
    const h = (value / largest) * (height / 2 - 1);
    a.fillRect(x, height / 2 - Math.max(h, 0), Math.max(1, Math.ceil(width / K)), Math.abs(h));
  });
}
