// The gallery's grid (grid.ts) is the Python renderer's (`gallery_columns`): the columns of
// every size 1 … 16 that fixtures/grid.json holds, and no tile alone on a row.
import { readFileSync } from "node:fs";
import { join } from "node:path";
import { describe, expect, it } from "vitest";
import { gridColumns } from "../src/grid";

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
});
