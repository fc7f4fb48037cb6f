// Every key is bound once: the page's keys (keys.ts) and the show's (show-control.ts), both from
// the tables that bind them and write the help's rows.
import { describe, expect, it } from "vitest";
import { PAGE_KEYS } from "../src/keys";
import { SHOW_KEYS } from "../src/show-control";

const bound = [...PAGE_KEYS, ...SHOW_KEYS].flatMap(([keys]) => [...keys]);

describe("keys", () => {
  it("binds each key once, the page's and the show's together", () => {
    const twice = bound.filter((key, i) => bound.indexOf(key) !== i);
    expect(twice).toEqual([]);
  });

  it("names keys as keydown events give them (a letter in lower case)", () => {
    for (const key of bound) expect(key.length === 1 ? key.toLowerCase() : key).toBe(key);
  });

  it("loops the song with L and the show's cue with C", () => {
    const what = (key: string) => [...PAGE_KEYS, ...SHOW_KEYS].find(([keys]) => keys.includes(key))?.[1];
    expect(what("l")).toBe("loop the song");
    expect(what("c")).toBe("loop this cue");
  });
});
