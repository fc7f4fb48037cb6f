// The gallery's history tree: breeding from an earlier generation starts a branch and keeps
// every later generation.
import { describe, expect, it } from "vitest";
import { History } from "../src/history";

describe("History", () => {
  it("keeps later generations when breeding from an earlier one (a branch)", () => {
    const history = new History<string>();
    expect(history.current).toBe(-1);
    history.add(["a"], null, "cat, song");
    history.add(["b"], 0);
    history.add(["c"], 1);
    history.current = 1; // back to generation 2, breed again
    history.add(["d"], 1);
    expect(history.size).toBe(4);
    expect(history.current).toBe(3);
    expect(history.generations.map((g) => g.mappings[0])).toEqual(["a", "b", "c", "d"]);
    expect(history.entries().map((e) => [e.index, e.depth])).toEqual(
      [[0, 0], [1, 1], [2, 2], [3, 2]]);
    expect(history.entries()[0].label).toBe("1 · first · cat, song");
    expect(history.entries()[3].label).toBe("    └ 4 · bred from 2");
  });

  it("steps through the generations in tree order, staying at the ends", () => {
    const history = new History<number>();
    history.add([0], null);
    history.add([1], 0);
    history.add([2], null, "new song"); // a second first generation
    history.add([3], 0);
    expect(history.entries().map((e) => e.index)).toEqual([0, 1, 3, 2]);
    history.current = 1;
    expect(history.neighbour(1)).toBe(3);
    expect(history.neighbour(-1)).toBe(0);
    history.current = 0;
    expect(history.neighbour(-1)).toBe(0);
    history.current = 2;
    expect(history.neighbour(1)).toBe(2);
  });
});
