// A session file opened in a server started again (docs/web.md#what-a-reload-shows): the
// library's ids are new, and the file's models, rigs and songs are found by their names.
import { describe, expect, it } from "vitest";
import type { Library } from "../src/api";
import { matched, named, rememberNames, sessionOf, without } from "../src/session";

const mesh = (id: string, name: string) => ({ id, name, k: 8, vertices: 9, ready: true,
  job: null });
const history = { generations: [], current: 0, selected: [] };

describe("a session file in another run of the server", () => {
  const before: Library = { meshes: [mesh("old-cat", "cat.obj")], mappings: [],
    songs: [{ id: "old-song", name: "song.wav", duration: 6 }],
    rigs: [{ id: "old-hand", name: "hand", ready: true }] };
  rememberNames(before);
  const file = named(sessionOf({ "old-cat": history }, {}, { id: "old-song", time: 2 },
    { kind: "rig", id: "old-hand" }));

  it("finds each model, rig and song by its name", () => {
    const now: Library = { meshes: [mesh("new-cat", "cat.obj")], mappings: [],
      songs: [{ id: "new-song", name: "song.wav", duration: 6 }],
      rigs: [{ id: "new-hand", name: "hand", ready: true }] };
    const { session, count, missing } = matched(file, now);
    expect(Object.keys(session.histories)).toEqual(["new-cat"]);
    expect([count, missing]).toEqual([1, ""]);
    expect(session.names).toEqual({ "new-cat": "cat.obj", "new-song": "song.wav",
      "new-hand": "hand" });
    expect(session.song).toEqual({ id: "new-song", time: 2 });
    expect(session.model).toEqual({ kind: "rig", id: "new-hand" });
  });

  it("names only what the session holds", () => {
    expect(file.names).toEqual({ "old-cat": "cat.obj", "old-song": "song.wav",
      "old-hand": "hand" });
  });

  it("keeps an id whose name is missing or twice in the library", () => {
    const now: Library = { meshes: [mesh("a", "cat.obj"), mesh("b", "cat.obj")], mappings: [],
      songs: [], rigs: [] };
    const { session, count, missing } = matched(file, now);
    expect(Object.keys(session.histories)).toEqual(["old-cat"]);
    expect(count).toBe(0); // said, not guessed: one line
    expect(missing).toBe("not served any more: song.wav, hand; served twice, not guessed: cat.obj");
    expect(session.song?.id).toBe("old-song");
    expect(session.model?.id).toBe("old-hand");
  });

  it("keeps the ids the library still has (a reload of the same run)", () => {
    expect(matched(file, before)).toEqual({ session: file, count: 1, missing: "" });
  });
});

describe("a model removed on purpose", () => {
  it("leaves the session with nothing of it", () => {
    const session = { ...sessionOf({ cat: history, bunny: history }, { hand: {
      generations: [], generation: 0, selected: [], player: null } },
    { id: "song", time: 1 }, { kind: "mesh", id: "cat" }),
    names: { cat: "cat.obj", bunny: "bunny.obj", hand: "hand", song: "song.wav" } } as const;
    const left = without(session, "cat");
    expect(Object.keys(left.histories)).toEqual(["bunny"]);
    expect(left.names).toEqual({ bunny: "bunny.obj", hand: "hand", song: "song.wav" });
    expect(left.model).toBeUndefined();
    expect(left.song).toEqual({ id: "song", time: 1 });
    const noHand = without(left, "hand");
    expect(noHand.rigs).toEqual({});
    expect(without(noHand, "song").song).toBeUndefined();
  });
});
