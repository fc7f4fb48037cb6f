// URL options and the gallery-size rule (api/config): a bad ?size= falls back to the default
// with a message, never a hung page.
import { describe, expect, it } from "vitest";
import {
  fewerTiles, galleryRule, gallerySize, readOptions, sizeChoices, wantsHooks,
} from "../src/options";

const rule = { min: 2, max: 16, default: 8 };

describe("gallery size", () => {
  it("takes any integer of the rule, odd ones included", () => {
    for (const size of [2, 3, 9, 16]) {
      expect(gallerySize(String(size), rule)).toEqual({ size, problem: null });
    }
    expect(gallerySize(null, rule)).toEqual({ size: 8, problem: null });
  });

  it("falls back to the default with a message outside the rule or for non-integers", () => {
    for (const raw of ["1", "17", "0", "-4", "6.5", "abc", "", "1e1", "0x8"]) {
      const { size, problem } = gallerySize(raw, rule);
      expect(size).toBe(8);
      expect(problem).toContain(`?size=${raw} is not a gallery size`);
      expect(problem).toContain("from 2 to 16");
    }
  });

  it("offers every size from 4 to the maximum, and a smaller current one", () => {
    expect(sizeChoices(rule, 8)).toEqual([4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15, 16]);
    expect(sizeChoices(rule, 2)[0]).toBe(2);
    expect(sizeChoices({ min: 6, max: 8, default: 6 }, 6)).toEqual([6, 7, 8]);
  });

  it("leaves the size to the server when its rule could not be read", () => {
    expect(gallerySize("5", null)).toEqual({ size: 5, problem: null });
    expect(gallerySize("40", null)).toEqual({ size: 40, problem: null }); // the server says no
    expect(gallerySize(null, null)).toEqual({ size: null, problem: null });
    expect(gallerySize("abc", null)).toEqual({ size: null, problem: null });
    expect(sizeChoices(null, 8)).toEqual([8]);
  });

  it("offers fewer tiles when the frame rate is too low", () => {
    expect(fewerTiles(8, 10, 20, 2)).toBe(4);
    expect(fewerTiles(16, 5, 20, 2)).toBe(4);
    expect(fewerTiles(4, 2, 20, 2)).toBe(2);
    expect(fewerTiles(2, 5, 20, 2)).toBeNull();
    expect(fewerTiles(8, 19, 20, 2)).toBe(7);
  });

  it("checks the server's answer", () => {
    expect(galleryRule({ gallery: rule })).toEqual(rule);
    expect(() => galleryRule({})).toThrow(/api\/config/);
    expect(() => galleryRule({ gallery: { min: 2, max: 16, default: 20 } })).toThrow();
    expect(() => galleryRule({ gallery: { min: "2", max: 16, default: 8 } })).toThrow();
  });
});

describe("URL options", () => {
  it("reads every option", () => {
    const options = readOptions("?size=6&mesh=m&song=s&mapping=p&view=player&half&render"
      + "&bare&path=cpu&batch=4");
    expect(options).toMatchObject({ size: "6", mesh: "m", song: "s", mapping: "p",
      view: "player", half: true, render: true, test: false, bare: true, path: "cpu", batch: 4 });
    expect(readOptions("?half=0").half).toBe(false);
    expect(readOptions("").half).toBeNull();
    expect(readOptions("?path=tpu").path).toBeNull();
    expect(readOptions("").view).toBeNull();
    expect(readOptions("?view=gallery").view).toBe("gallery");
    expect(readOptions("?aa=0").aa).toBe(false);
    expect(readOptions("?aa").aa).toBe(true);
    expect(readOptions("").aa).toBeNull();
  });

  it("reads the frame rate to aim at, 1 to 120 fps, else the default's null", () => {
    expect(readOptions("?fps=60").fps).toBe(60);
    expect(readOptions("?fps=1").fps).toBe(1);
    expect(readOptions("?fps=120").fps).toBe(120);
    expect(readOptions("?fps=29.97").fps).toBe(29.97);
    for (const bad of ["", "?fps", "?fps=0", "?fps=121", "?fps=-5", "?fps=fast", "?fps=NaN"]) {
      expect(readOptions(bad).fps).toBeNull();
    }
  });

  it("installs the hooks only for ?render and ?test", () => {
    expect(wantsHooks(readOptions(""))).toBe(false);
    expect(wantsHooks(readOptions("?size=4&view=player"))).toBe(false);
    expect(wantsHooks(readOptions("?render"))).toBe(true);
    expect(wantsHooks(readOptions("?test"))).toBe(true);
  });
});
