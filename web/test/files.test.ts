// Files given to the page together (docs/web.md#http-api): a model with the files it names goes
// as one zip, read back here with fflate; and the model the page opens first (a rig given first
// to `serve` opens as a rig).
import { describe, expect, it } from "vitest";
import { unzipSync } from "three/examples/jsm/libs/fflate.module.js";
import { firstRig } from "../src/session";
import type { Library } from "../src/api";
import { suffixesOf, together } from "../src/files";

const file = (name: string, text: string) => new File([text], name);
// As the server announces them (GET api/config: eigendance.inputs.model.published_suffixes).
const suffixes = suffixesOf({ suffixes: { mesh: [".obj", ".gltf", ".glb"], rig: [".json"],
  audio: [".wav", ".mp3"], mapping: [".json"], archive: [".zip"],
  companion: [".bin", ".mtl", ".png"] } });

describe("several files", () => {
  it("zips a .gltf with its .bin and textures, and leaves the song alone", async () => {
    const files = [file("ship.gltf", "{}"), file("ship_data.bin", "BIN"),
      file("song.wav", "RIFF"), file("hull.png", "PNG")];
    const uploads = await together(files, suffixes, ["/ship/ship.gltf", "/ship/ship_data.bin",
      "/song.wav", "/ship/textures/hull.png"]);
    expect(uploads.map((f) => f.name)).toEqual(["ship.zip", "song.wav"]);
    const members = unzipSync(new Uint8Array(await uploads[0].arrayBuffer()));
    expect(Object.keys(members).sort()).toEqual(["ship/ship.gltf", "ship/ship_data.bin",
      "ship/textures/hull.png"]);
    expect(new TextDecoder().decode(members["ship/ship_data.bin"])).toBe("BIN");
  });

  it("zips an OBJ with its MTL, and sends lone files as they are", async () => {
    const uploads = await together([file("robot.obj", "v"), file("robot.mtl", "newmtl")],
      suffixes);
    expect(uploads.map((f) => f.name)).toEqual(["robot.zip"]);
    const alone = [file("bunny.obj", "v"), file("tune.mp3", "ID3"), file("x.bin", "?")];
    expect((await together(alone.slice(0, 2), suffixes)).map((f) => f.name))
      .toEqual(["bunny.obj", "tune.mp3"]);
    // companions without a model: the server says what it cannot read
    expect((await together([alone[2]], suffixes)).map((f) => f.name)).toEqual(["x.bin"]);
  });

  it("sends each file alone without the server's suffixes; refuses a malformed list", async () => {
    const files = [file("robot.obj", "v"), file("robot.mtl", "newmtl")];
    expect((await together(files, null)).map((f) => f.name)).toEqual(["robot.obj", "robot.mtl"]);
    expect(suffixesOf({ suffixes: { mesh: ".obj" } })).toBeNull();
    expect(suffixesOf({ gallery: {} })).toBeNull();
  });
});

describe("the first model", () => {
  const library = (over: Partial<Library>): Library => ({ meshes: [], songs: [], mappings: [],
    rigs: [{ id: "hand", name: "hand", ready: false, origin: "built-in" }], ...over });

  it("is the rig given first to serve", () => {
    const rigs = [{ id: "hand", name: "hand", ready: false, origin: "built-in" },
      { id: "stag", name: "Stag.glb", ready: true, origin: "file" }];
    expect(firstRig(library({ rigs, first: { kind: "rig", id: "stag" } }), null)).toBe("stag");
    expect(firstRig(library({ rigs, first: { kind: "rig", id: "stag" } }), "m1")).toBeNull();
  });

  it("is a mesh when there is one; a rig added from a file when it is alone", () => {
    const meshes = [{ id: "m1", name: "cat.obj", k: 8, vertices: 9, ready: true, job: null }];
    const rigs = [{ id: "hand", name: "hand", ready: false, origin: "built-in" },
      { id: "fox", name: "Fox.glb", ready: true, origin: "upload" }];
    expect(firstRig(library({ meshes, rigs, first: { kind: "mesh", id: "m1" } }), null))
      .toBeNull();
    expect(firstRig(library({ rigs }), null)).toBe("fox");
    expect(firstRig(library({}), null)).toBeNull(); // only built-in rigs: the page asks for a model
  });
});
