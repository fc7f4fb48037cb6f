// The gallery's grid (docs/design.md#rendering): how many columns S tiles take, the page's and
// the video renderer's one rule (`eigendance.export.renderer.gallery_columns`; Vitest checks
// this port against numbers it writes).

/**
 * Columns of a grid of `count` tiles: ⌈√(1.5·S)⌉ (at most S), a grid about 1.5 times wider
 * than tall, then fewer while the last row would be less than half full, so no tile is left
 * alone on a row (16 tiles: 4 × 4, not 5 + 5 + 5 + 1).
 */
export function gridColumns(count: number): number {
  let columns = Math.max(1, Math.min(count, Math.ceil(Math.sqrt(count * 1.5))));
  while (columns > 1) {
    const last = count - (Math.ceil(count / columns) - 1) * columns;
    if (2 * last >= columns) break;
    columns--;
  }
  return columns;
}
