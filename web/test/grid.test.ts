// The gallery's grid (grid.ts) is the Python renderer's (`gallery_columns`): the columns of
// every size 1 … 16 that fixtures/grid.json holds, and no tile alone on a row.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { fittedColumns, gridColumns } from "../src/grid";

const reference = JSON.parse(readFileSync(join(__dirname, "fixtures", "grid.json"), "utf8"));

describe("grid", () => {
  it("has Python's columns for every size", () => {
    for (const [count, columns] of Object.entries(reference.columns)) {
      expect(gridColumns(Number(count))).toBe(columns);
    }
  });

  it("leaves no tile alone on a row of a wider grid", () => {
    for (let count = 2; count <= 16; count++) {
      const columns = gridColumns(count);
      const last = count - (Math.ceil(count / columns) - 1) * columns;
      expect(columns === 1 || last >= 2, `${count} tiles`).toBe(true);
      expect(2 * last).toBeGreaterThanOrEqual(columns);
    }
  });

  it("shapes a rig's tiles to the rig: tall tiles for a standing figure, wide for a lying one", () => {
    // 16 tiles in 1260 × 640 px, gap 6, caption 18: a figure 0.3 as wide as tall draws largest
    // in 8 columns of 2 rows (tiles 152 × 299 px: drawn 299 px tall; 4 × 4: 138 px), one 4 times
    // wider than tall in 4 × 4 (tiles 310 × 138 px: 78 px tall), one 10 times wider in 2
    // columns of 8 rows (tiles 627 × 57 px: 57 px tall; 4 × 4: 31 px)
    expect(fittedColumns(16, 1260, 640, 0.3)).toBe(8);
    expect(fittedColumns(16, 1260, 640, 4)).toBe(4);
    expect(fittedColumns(16, 1260, 640, 10)).toBe(2);
    for (const aspect of [0.3, 1, 4, 10]) {
      const columns = fittedColumns(16, 1260, 640, aspect);
      const last = 16 - (Math.ceil(16 / columns) - 1) * columns;
      expect(columns === 1 || 2 * last >= columns).toBe(true);
    }
    expect(fittedColumns(16, 0, 0, 1)).toBe(gridColumns(16)); // hidden: the gallery's rule
  });
});
