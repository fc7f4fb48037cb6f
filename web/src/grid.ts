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

/**
 * Columns of a grid of `count` tiles of a model `aspect` times wider than tall (as the camera
 * sees it) in a `width` × `height` area (CSS px; tiles `gap` apart, each with a `caption` row):
 * the count that draws the model largest — a tall character gets tall tiles, a long animal wide
 * ones — again with no last row less than half full (the rig galleries: docs/design.md#the-floor).
 */
export function fittedColumns(count: number, width: number, height: number, aspect: number,
                              gap = 6, caption = 18): number {
  if (!(width > 0 && height > 0 && aspect > 0) || count < 1) return gridColumns(count);
  let best = 1, largest = -1;
  for (let columns = 1; columns <= count; columns++) {
    const rows = Math.ceil(count / columns);
    if (columns > 1 && 2 * (count - (rows - 1) * columns) < columns) continue;
    const tileWidth = (width - (columns - 1) * gap) / columns;
    const tileHeight = (height - (rows - 1) * gap) / rows - caption;
    const scale = Math.min(tileWidth / aspect, tileHeight); // the model's drawn height
    if (scale > largest * 1.001) { best = columns; largest = scale; }
  }
  return best;
}
