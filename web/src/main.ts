// eigendance web app: animated gallery and live player, in sync with the music (DESIGN §4, §6).
import * as THREE from "three";
import { OrbitControls } from "three/examples/jsm/controls/OrbitControls.js";
import * as api from "./api";
import type { Basis, Spectrum } from "./bundle";
import { Deformer, TILE_COLORS, maxHarmonicsOnGPU } from "./deform";
import {
  deformCPU, filterValues, prepare, shaderWeights, smoothed, spectrumAt,
} from "./filter";
import type { Mapping, Prepared } from "./filter";
import "./style.css";

const params = new URLSearchParams(location.search);
const renderMode = params.has("render");
const $ = <T extends HTMLElement = HTMLElement>(id: string) => document.getElementById(id) as T;

// --- state ------------------------------------------------------------------------------------
interface Tile { element: HTMLElement; view: HTMLElement; transfer: HTMLCanvasElement;
  amplification: HTMLCanvasElement; }

const state = {
  library: null as api.Library | null,
  meshId: "", songId: "",
  basis: null as Basis | null,
  spectrum: null as Spectrum | null,
  values: null as Float32Array | null, // spectrogram values after the extra smoothing
  deformer: null as Deformer | null,
  generations: [] as Mapping[][],
  generation: 0,
  prepared: [] as Prepared[],
  selected: new Set<number>(),
  size: Number(params.get("size") ?? 8),
  tiles: [] as Tile[],
  view: (params.get("view") === "player" ? "player" : "gallery") as "gallery" | "player",
  playerMapping: null as Mapping | null,
  playerPrepared: null as Prepared | null,
  gain: 1, smoothing: 0, normalBlend: 0.4, shading: "smooth", harmonic: -1, harmonicScale: 1,
  explicitTime: null as number | null,
  path: "gpu" as "gpu" | "cpu",
  audio: { context: null as AudioContext | null, buffer: null as AudioBuffer | null,
    source: null as AudioBufferSourceNode | null, output: null as GainNode | null,
    startedAt: 0, offset: 0, playing: false },
  frameMs: 0,
};

const canvas = $<HTMLCanvasElement>("gl");
const renderer = new THREE.WebGLRenderer({ canvas, antialias: false,
  preserveDrawingBuffer: true, powerPreference: "high-performance" });
renderer.setPixelRatio(Math.min(window.devicePixelRatio, 2));
renderer.autoClear = false;
const tileCamera = new THREE.PerspectiveCamera(32, 1, 0.1, 50);
const playerCamera = new THREE.PerspectiveCamera(35, 1, 0.05, 50);
const controls = new OrbitControls(playerCamera, $("player-area"));
controls.enableDamping = false;
controls.addEventListener("change", () => requestDraw());
const bandBuffer = new Float32Array(1024);

function status(text: string): void { $("status").textContent = text; }

// --- time ---------------------------------------------------------------------------------------
function duration(): number { return state.spectrum?.duration ?? 0; }

function clockTime(): number {
  const audio = state.audio;
  return audio.playing && audio.context ? audio.context.currentTime - audio.startedAt
    : audio.offset;
}

function now(): number {
  if (state.explicitTime !== null) return state.explicitTime;
  const t = clockTime();
  if (state.audio.playing && t >= duration()) { // the end of the song: back to the start
    stop();
    state.audio.offset = 0;
    return 0;
  }
  return t;
}

function ensureAudio(): AudioContext {
  if (!state.audio.context) {
    state.audio.context = new AudioContext();
    state.audio.output = state.audio.context.createGain();
    state.audio.output.connect(state.audio.context.destination);
  }
  return state.audio.context;
}

async function loadAudio(songId: string): Promise<void> {
  stop();
  state.audio.buffer = null;
  try {
    const context = ensureAudio();
    state.audio.buffer = await context.decodeAudioData(await api.audioBytes(songId));
  } catch (error) {
    status(`audio: ${(error as Error).message}`);
  }
}

function play(): void {
  const audio = state.audio;
  if (audio.playing || !audio.buffer) return;
  const context = ensureAudio();
  void context.resume();
  const source = context.createBufferSource();
  source.buffer = audio.buffer;
  source.connect(audio.output!);
  source.start(0, audio.offset);
  audio.source = source;
  audio.startedAt = context.currentTime - audio.offset;
  audio.playing = true;
  state.explicitTime = null;
  $("play").textContent = "❚❚";
}

function stop(): void {
  const audio = state.audio;
  if (!audio.playing) return;
  audio.offset = Math.min(clockTime(), duration());
  audio.playing = false;
  try { audio.source?.stop(); } catch { /* already stopped */ }
  audio.source = null;
  $("play").textContent = "▶";
}

function seek(t: number): void {
  const wasPlaying = state.audio.playing;
  stop();
  state.audio.offset = Math.max(0, Math.min(t, duration()));
  if (wasPlaying) play();
  requestDraw();
}

// --- gallery --------------------------------------------------------------------------------
function currentMappings(): Mapping[] { return state.generations[state.generation] ?? []; }

function setGeneration(index: number): void {
  state.generation = Math.max(0, Math.min(index, state.generations.length - 1));
  state.selected.clear();
  const k = state.basis!.k;
  state.prepared = currentMappings().map((m) => prepare(m, k));
  buildTiles();
  $("generation").textContent = `generation ${state.generation + 1} of ${state.generations.length}`;
  $<HTMLButtonElement>("back").disabled = state.generation === 0;
  $<HTMLButtonElement>("forward").disabled = state.generation >= state.generations.length - 1;
  updateBreedButton();
  requestDraw();
}

function updateBreedButton(): void {
  $<HTMLButtonElement>("breed").disabled = state.selected.size === 0;
}

function buildTiles(): void {
  const container = $("tiles");
  container.innerHTML = "";
  const mappings = currentMappings();
  const columns = Math.ceil(Math.sqrt(mappings.length * 1.5));
  container.style.setProperty("--columns", String(columns));
  let largest = 1e-12;
  for (const m of mappings) for (const a of m.amplification) largest = Math.max(largest, Math.abs(a));
  state.tiles = mappings.map((mapping, index) => {
    const element = document.createElement("div");
    element.className = "tile";
    element.dataset.index = String(index);
    element.innerHTML = `<span class="label">#${index + 1}</span>
      <div class="actions"><button class="open" title="open in the player">open</button>
      <button class="save" title="download this mapping (JSON)">save</button></div>
      <div class="view"></div>
      <div class="plots"><canvas class="transfer" width="160" height="34" title="transfer: band → harmonic"></canvas>
      <canvas class="amplification" width="160" height="34" title="amplification per harmonic"></canvas></div>`;
    element.addEventListener("click", (event) => {
      const target = event.target as HTMLElement;
      if (target.closest(".open")) { openInPlayer(mapping); return; }
      if (target.closest(".save")) { download(mapping, `mapping-g${state.generation + 1}-${index + 1}.json`); return; }
      toggleSelected(index);
    });
    container.appendChild(element);
    const tile = { element, view: element.querySelector(".view") as HTMLElement,
      transfer: element.querySelector(".transfer") as HTMLCanvasElement,
      amplification: element.querySelector(".amplification") as HTMLCanvasElement };
    drawPlots(tile, mapping, largest, TILE_COLORS[index % TILE_COLORS.length]);
    return tile;
  });
}

function toggleSelected(index: number): void {
  if (state.selected.has(index)) state.selected.delete(index); else state.selected.add(index);
  state.tiles[index]?.element.classList.toggle("selected", state.selected.has(index));
  updateBreedButton();
}

function drawPlots(tile: Tile, mapping: Mapping, largest: number, color: number): void {
  const css = `#${color.toString(16).padStart(6, "0")}`;
  const t = tile.transfer.getContext("2d")!;
  const { width, height } = tile.transfer;
  t.clearRect(0, 0, width, height);
  t.strokeStyle = css;
  t.lineWidth = 1.5;
  t.beginPath();
  mapping.transfer.forEach((value, b) => {
    const x = (b / Math.max(1, mapping.transfer.length - 1)) * (width - 2) + 1;
    const y = height - 2 - value * (height - 4);
    if (b === 0) t.moveTo(x, y); else t.lineTo(x, y);
  });
  t.stroke();
  const a = tile.amplification.getContext("2d")!;
  a.clearRect(0, 0, width, height);
  a.fillStyle = "#444";
  a.fillRect(0, height / 2, width, 1);
  a.fillStyle = css;
  const K = mapping.amplification.length;
  mapping.amplification.forEach((value, v) => {
    const x = Math.floor((v / K) * width);
    const h = (value / largest) * (height / 2 - 1);
    a.fillRect(x, height / 2 - Math.max(h, 0), Math.max(1, Math.ceil(width / K)), Math.abs(h));
  });
}

async function newGallery(): Promise<void> {
  status("making the gallery…");
  const mappings = await api.gallery(state.meshId, state.songId, state.size);
  state.generations = [mappings];
  setGeneration(0);
  status("");
}

async function breedSelected(seed?: number): Promise<void> {
  const parents = [...state.selected].sort((a, b) => a - b).map((i) => currentMappings()[i]);
  if (!parents.length) return;
  status("breeding…");
  const children = await api.breed(parents, state.size,
    seed ?? Math.floor(Math.random() * 2 ** 31));
  state.generations = state.generations.slice(0, state.generation + 1);
  state.generations.push(children);
  setGeneration(state.generations.length - 1);
  status("");
}

function download(mapping: Mapping, name: string): void {
  const blob = new Blob([JSON.stringify(mapping, null, 1)], { type: "application/json" });
  const link = document.createElement("a");
  link.href = URL.createObjectURL(blob);
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

// --- player ---------------------------------------------------------------------------------
function openInPlayer(mapping: Mapping): void {
  state.playerMapping = mapping;
  state.playerPrepared = prepare(mapping, state.basis!.k);
  setView("player");
}

function setView(view: "gallery" | "player"): void {
  state.view = view;
  $("gallery-view").hidden = view !== "gallery";
  $("player-view").hidden = view !== "player";
  $("tab-gallery").classList.toggle("active", view === "gallery");
  $("tab-player").classList.toggle("active", view === "player");
  if (view === "player" && !state.playerMapping && currentMappings().length) {
    state.playerMapping = currentMappings()[0];
    state.playerPrepared = prepare(state.playerMapping, state.basis!.k);
  }
  updatePlayerInfo();
  requestDraw();
}

function updatePlayerInfo(): void {
  const b = state.basis;
  if (!b) return;
  const h = state.harmonic;
  const harmonic = h >= 0 ? ` · harmonic ${h}: λ = ${b.eigenvalues[h].toPrecision(4)}` : "";
  $("player-info").textContent = `${b.name}: ${b.n} vertices, k = ${b.k}, ` +
    `${state.path.toUpperCase()} deformation, ${state.frameMs.toFixed(0)} ms/frame${harmonic}`;
}

// --- recording -------------------------------------------------------------------------------
let recorder: MediaRecorder | null = null;
function toggleRecord(): void {
  if (recorder) { recorder.stop(); return; }
  const stream = canvas.captureStream(30);
  const context = ensureAudio();
  const destination = context.createMediaStreamDestination();
  state.audio.output!.connect(destination);
  destination.stream.getAudioTracks().forEach((track) => stream.addTrack(track));
  const type = ["video/webm;codecs=vp9,opus", "video/webm;codecs=vp8,opus", "video/webm"]
    .find((t) => MediaRecorder.isTypeSupported(t)) ?? "video/webm";
  const chunks: Blob[] = [];
  recorder = new MediaRecorder(stream, { mimeType: type });
  recorder.ondataavailable = (event) => { if (event.data.size) chunks.push(event.data); };
  recorder.onstop = () => {
    state.audio.output!.disconnect(destination);
    const link = document.createElement("a");
    link.href = URL.createObjectURL(new Blob(chunks, { type: "video/webm" }));
    link.download = "eigendance.webm";
    link.click();
    recorder = null;
    $("record").textContent = "● record";
  };
  recorder.start(250);
  $("record").textContent = "■ stop";
  play();
}

// --- drawing -------------------------------------------------------------------------------------
let drawRequested = false;
function requestDraw(): void { drawRequested = true; }

function resize(): void {
  const width = window.innerWidth, height = window.innerHeight;
  const size = renderer.getSize(new THREE.Vector2());
  if (size.x !== width || size.y !== height) renderer.setSize(width, height, false);
}

function tileOptions(index: number) {
  const wireframe = state.shading === "wireframe";
  return { color: TILE_COLORS[index % TILE_COLORS.length], wireframe,
    normalBlend: state.shading === "flat" ? 0 : state.normalBlend,
    harmonic: state.view === "player" ? state.harmonic : -1,
    harmonicScale: state.harmonicScale };
}

function weightsFor(prepared: Prepared, bandValues: Float32Array): Float32Array {
  const phi = filterValues(prepared, bandValues, state.gain);
  return shaderWeights(state.basis!, phi);
}

function bandValuesAt(t: number): Float32Array {
  const s = state.spectrum!;
  return spectrumAt(s, t, bandBuffer.subarray(0, s.bands), state.values ?? s.values);
}

function renderInto(element: HTMLElement, camera: THREE.PerspectiveCamera, weights: Float32Array,
                    index: number, positions: THREE.Texture | null): void {
  const deformer = state.deformer!;
  const rect = element.getBoundingClientRect();
  const height = renderer.domElement.clientHeight;
  if (rect.width < 2 || rect.height < 2 || rect.bottom < 0 || rect.top > height) return;
  const x = rect.left, y = height - rect.bottom;
  renderer.setViewport(x, y, rect.width, rect.height);
  renderer.setScissor(x, y, rect.width, rect.height);
  camera.aspect = rect.width / rect.height;
  camera.updateProjectionMatrix();
  const cpu = deformer.useCPU ? deformCPU(state.basis!, weights, cpuBuffer()) : null;
  deformer.setTile(weights, cpu, tileOptions(index), positions);
  renderer.render(deformer.scene, camera);
}

let cpuPositions: Float32Array | null = null;
function cpuBuffer(): Float32Array {
  const n3 = state.basis!.n * 3;
  if (!cpuPositions || cpuPositions.length !== n3) cpuPositions = new Float32Array(n3);
  return cpuPositions;
}

function drawSpectrum(bandValues: Float32Array): void {
  const strip = $<HTMLCanvasElement>("spectrum");
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

function drawFrame(t: number): void {
  if (!state.deformer || !state.spectrum) return;
  const start = performance.now();
  resize();
  const bandValues = bandValuesAt(t);
  drawSpectrum(bandValues);
  renderer.setScissorTest(false);
  renderer.setClearColor(0x15171c, 1);
  renderer.clear();
  renderer.setScissorTest(true);
  if (state.view === "gallery") {
    const weights = state.prepared.map((prepared) => weightsFor(prepared, bandValues));
    // GPU path: every tile's positions first (batched passes), then the surfaces.
    const positions = state.deformer.useCPU ? null : state.deformer.computePositions(weights);
    state.tiles.forEach((tile, index) => {
      renderInto(tile.view, tileCamera, weights[index], index, positions?.[index] ?? null);
    });
  } else if (state.playerPrepared) {
    renderInto($("player-area"), playerCamera, weightsFor(state.playerPrepared, bandValues),
      Math.max(0, currentMappings().indexOf(state.playerMapping!)), null);
  }
  renderer.setScissorTest(false);
  const elapsed = performance.now() - start;
  state.frameMs = state.frameMs ? 0.9 * state.frameMs + 0.1 * elapsed : elapsed;
  const seekBar = $<HTMLInputElement>("seek");
  if (document.activeElement !== seekBar) seekBar.value = String(t);
  const seconds = Math.floor(t);
  $("clock").textContent = `${Math.floor(seconds / 60)}:${String(seconds % 60).padStart(2, "0")}`;
}

function loop(): void {
  if ((state.audio.playing && state.explicitTime === null) || drawRequested) {
    drawRequested = false;
    drawFrame(now());
    if (state.view === "player" && Math.random() < 0.05) updatePlayerInfo();
  }
  requestAnimationFrame(loop);
}

/** Wait until the GPU has finished the frame (a 1-pixel read forces it). */
function finish(): void {
  const gl = renderer.getContext();
  gl.readPixels(0, 0, 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, new Uint8Array(4));
}

// --- choosing the deformation path (DESIGN §6) -----------------------------------------------------
function choosePath(): void {
  const deformer = state.deformer!;
  const forced = params.get("path");
  if (state.basis!.k > maxHarmonicsOnGPU(renderer)) {
    deformer.useCPU = true;
  } else if (forced === "gpu" || forced === "cpu") {
    deformer.useCPU = forced === "cpu";
  } else {
    const time = (useCPU: boolean) => {
      deformer.useCPU = useCPU;
      drawFrame(1); finish(); // warm-up: shader compile, uploads
      const start = performance.now();
      for (let i = 0; i < 2; i++) { drawFrame(1.5 + i); finish(); }
      return (performance.now() - start) / 2;
    };
    const gpu = time(false), cpu = time(true);
    deformer.useCPU = cpu < gpu;
    console.info(`eigendance: GPU ${gpu.toFixed(1)} ms, CPU ${cpu.toFixed(1)} ms per frame`);
  }
  state.path = deformer.useCPU ? "cpu" : "gpu";
  state.frameMs = 0;
}

// --- loading ----------------------------------------------------------------------------------
function fillSelect(id: string, items: { id: string; name: string }[], chosen: string): void {
  const select = $<HTMLSelectElement>(id);
  select.innerHTML = "";
  for (const item of items) {
    const option = document.createElement("option");
    option.value = item.id;
    option.textContent = item.name;
    option.selected = item.id === chosen;
    select.appendChild(option);
  }
}

async function refreshLibrary(): Promise<api.Library> {
  state.library = await api.library();
  fillSelect("mesh", state.library.meshes, state.meshId);
  fillSelect("song", state.library.songs, state.songId);
  return state.library;
}

async function waitForBasis(mesh: api.MeshInfo): Promise<void> {
  if (mesh.ready || !mesh.job) return;
  await api.followJob(mesh.job.id, (job) => {
    status(`${mesh.name}: basis ${job.done}/${job.total} eigenpairs (${job.state})`);
  });
}

async function loadMesh(meshId: string): Promise<void> {
  const mesh = state.library!.meshes.find((m) => m.id === meshId);
  if (!mesh) throw new Error(`no mesh ${meshId}`);
  state.meshId = meshId;
  $<HTMLSelectElement>("mesh").value = meshId;
  await waitForBasis(mesh);
  status(`${mesh.name}: loading basis…`);
  // float16 harmonics on request (?half), or when float32 would exceed 128 MB (?half=0: never)
  const bytes = 16 * Math.ceil(mesh.k / 4) * mesh.vertices;
  const half = params.has("half") ? params.get("half") !== "0" : bytes > 128 * 2 ** 20;
  const basis = await api.basis(meshId, half);
  state.deformer?.dispose();
  state.basis = basis;
  state.deformer = new Deformer(basis, renderer, Number(params.get("batch") ?? 8));
  state.harmonic = -1;
  $<HTMLInputElement>("harmonic").value = "-1";
  $<HTMLInputElement>("harmonic").max = String(basis.k - 1);
  aimCameras(basis);
}

function aimCameras(basis: Basis): void {
  let radius = 0;
  for (let i = 0; i < basis.n * 3; i += 3) {
    radius = Math.max(radius, Math.hypot(basis.vertices[i], basis.vertices[i + 1], basis.vertices[i + 2]));
  }
  const distance = (radius * 1.15) / Math.sin(THREE.MathUtils.degToRad(16));
  const direction = new THREE.Vector3(0.55, 0.35, 1).normalize();
  tileCamera.position.copy(direction).multiplyScalar(distance);
  tileCamera.lookAt(0, 0, 0);
  playerCamera.position.copy(direction).multiplyScalar(distance * 0.95);
  controls.target.set(0, 0, 0);
  controls.update();
}

async function loadSong(songId: string): Promise<void> {
  state.songId = songId;
  $<HTMLSelectElement>("song").value = songId;
  state.spectrum = await api.spectrum(songId);
  state.values = smoothed(state.spectrum, state.smoothing);
  $<HTMLInputElement>("seek").max = String(state.spectrum.duration);
  if (!renderMode) await loadAudio(songId);
  else state.audio.offset = 0;
}

async function handleFiles(files: FileList | File[]): Promise<void> {
  for (const file of Array.from(files)) {
    try {
      status(`uploading ${file.name}…`);
      const result = await api.upload(file);
      const library = await refreshLibrary();
      if (!started) { // the library was incomplete: this file may complete it
        if (await loadFirst(library)) status(`${file.name} ready`);
        continue;
      }
      if (result.kind === "mesh") {
        await loadMesh(result.item.id);
        await newGallery();
        choosePath();
      } else if (result.kind === "song") {
        await loadSong(result.item.id);
      } else if (result.kind === "mapping") {
        openInPlayer(await api.getJSON<Mapping>(`api/mappings/${result.item.id}`));
      }
      status(`${file.name} ready`);
      requestDraw();
    } catch (error) {
      status(`${file.name}: ${(error as Error).message}`);
    }
  }
}

// --- controls ---------------------------------------------------------------------------------
function wireControls(): void {
  $("play").addEventListener("click", () => (state.audio.playing ? stop() : play()));
  $("seek").addEventListener("input", (e) => seek(Number((e.target as HTMLInputElement).value)));
  $("tab-gallery").addEventListener("click", () => setView("gallery"));
  $("tab-player").addEventListener("click", () => setView("player"));
  $("back").addEventListener("click", () => setGeneration(state.generation - 1));
  $("forward").addEventListener("click", () => setGeneration(state.generation + 1));
  $("breed").addEventListener("click", () => { void breedSelected(); });
  $("size").addEventListener("change", (e) => {
    state.size = Number((e.target as HTMLSelectElement).value);
    void newGallery();
  });
  $("mesh").addEventListener("change", async (e) => {
    await loadMesh((e.target as HTMLSelectElement).value);
    await newGallery();
    choosePath();
    status("");
  });
  $("song").addEventListener("change", async (e) => {
    await loadSong((e.target as HTMLSelectElement).value);
    requestDraw();
  });
  const slider = (id: string, apply: (v: number) => string) => {
    const input = $<HTMLInputElement>(id);
    const update = () => { $(`${id}-out`).textContent = apply(Number(input.value)); requestDraw(); };
    input.addEventListener("input", update);
  };
  slider("gain", (v) => { state.gain = v; return v.toFixed(2); });
  slider("smoothing", (v) => {
    state.smoothing = v;
    if (state.spectrum) state.values = smoothed(state.spectrum, v);
    return `${v.toFixed(2)} s`;
  });
  slider("blend", (v) => { state.normalBlend = v; return v.toFixed(2); });
  $("shading").addEventListener("change", (e) => {
    state.shading = (e.target as HTMLSelectElement).value;
    requestDraw();
  });
  $("harmonic").addEventListener("input", (e) => {
    const k = state.basis?.k ?? 1;
    const value = Math.min(k - 1, Math.max(-1, Math.floor(Number((e.target as HTMLInputElement).value))));
    state.harmonic = Number.isFinite(value) ? value : -1;
    state.harmonicScale = state.harmonic >= 0 ? state.deformer!.harmonicScale(state.harmonic) : 1;
    updatePlayerInfo();
    requestDraw();
  });
  $("record").addEventListener("click", toggleRecord);
  $("save-mapping").addEventListener("click", () => {
    if (state.playerMapping) download(state.playerMapping, "mapping.json");
  });
  $("load-mapping").addEventListener("change", async (e) => {
    const file = (e.target as HTMLInputElement).files?.[0];
    if (!file) return;
    try {
      const mapping = JSON.parse(await file.text()) as Mapping;
      if (mapping.format !== "eigendance.mapping") throw new Error("not an eigendance mapping");
      openInPlayer(mapping);
    } catch (error) { status(`${file.name}: ${(error as Error).message}`); }
  });
  $("upload").addEventListener("change", (e) => {
    const files = (e.target as HTMLInputElement).files;
    if (files) void handleFiles(files);
  });
  const drop = $("drop");
  window.addEventListener("dragover", (e) => { e.preventDefault(); drop.hidden = false; });
  drop.addEventListener("dragleave", () => { drop.hidden = true; });
  window.addEventListener("drop", (e) => {
    e.preventDefault();
    drop.hidden = true;
    if (e.dataTransfer?.files.length) void handleFiles(e.dataTransfer.files);
  });
  window.addEventListener("keydown", (e) => {
    if (e.code === "Space" && !(e.target instanceof HTMLInputElement)) {
      e.preventDefault();
      if (state.audio.playing) stop(); else play();
    }
  });
  window.addEventListener("resize", requestDraw);
}

// --- hooks for offline rendering and tests ---------------------------------------------------------
function mappingOf(tile: number | "player"): Prepared {
  if (tile === "player") return state.playerPrepared!;
  return state.prepared[tile];
}

const hooks = {
  ready: null as Promise<void> | null,
  /** Draw the frame at time t (seconds) and resolve when it is on the canvas. */
  async renderAt(t: number): Promise<void> {
    state.explicitTime = t;
    drawFrame(t);
    finish();
  },
  /** Back to the audio clock. */
  live(): void { state.explicitTime = null; requestDraw(); },
  /** Deformed positions (normalised, n*3) of a tile at time t, computed by the GPU shader and
   * read back from its float render target: the batched pass over every gallery tile, as drawn,
   * or with `single` the one-tile pass (the player's). */
  readPositions(tile: number | "player", t: number, single = false): number[] {
    const values = bandValuesAt(t);
    if (tile === "player" || single) {
      return Array.from(state.deformer!.readPositions([weightsFor(mappingOf(tile), values)]));
    }
    const weights = state.prepared.map((prepared) => weightsFor(prepared, values));
    return Array.from(state.deformer!.readPositions(weights, tile));
  },
  /** The same positions from the CPU path. */
  cpuPositions(tile: number | "player", t: number): number[] {
    const weights = weightsFor(mappingOf(tile), bandValuesAt(t));
    return Array.from(deformCPU(state.basis!, weights));
  },
  /** Downsampled RGBA pixels of each tile's view, read from the canvas (for tests). */
  tilePixels(step = 4): number[][] {
    const gl = renderer.getContext();
    const height = renderer.domElement.height;
    const ratio = renderer.getPixelRatio();
    return state.tiles.map((tile) => {
      const r = tile.view.getBoundingClientRect();
      const w = Math.floor(r.width * ratio), h = Math.floor(r.height * ratio);
      const pixels = new Uint8Array(w * h * 4);
      gl.readPixels(Math.floor(r.left * ratio), height - Math.floor(r.bottom * ratio), w, h,
        gl.RGBA, gl.UNSIGNED_BYTE, pixels);
      const out: number[] = [];
      for (let y = 0; y < h; y += step) {
        for (let x = 0; x < w; x += step) {
          const i = 4 * (y * w + x);
          out.push(pixels[i], pixels[i + 1], pixels[i + 2]);
        }
      }
      return out;
    });
  },
  mappings: () => currentMappings(),
  select: (index: number) => toggleSelected(index),
  breed: (seed?: number) => breedSelected(seed),
  back: () => setGeneration(state.generation - 1),
  setView: (view: "gallery" | "player") => setView(view),
  open: (index: number) => openInPlayer(currentMappings()[index]),
  upload: (file: File) => handleFiles([file]),
  info: () => ({
    meshId: state.meshId, songId: state.songId, n: state.basis?.n, k: state.basis?.k,
    path: state.path, batch: state.deformer?.batch, generation: state.generation, generations: state.generations.length,
    tiles: state.tiles.length, view: state.view, frameMs: state.frameMs,
    duration: duration(), selected: [...state.selected],
  }),
  setPath(path: "gpu" | "cpu"): void {
    state.deformer!.useCPU = path === "cpu";
    state.path = path;
  },
  /** Time the deformation alone of every tile (ms per frame), GPU or CPU path, for benchmarks. */
  timeDeformation(count: number, t0 = 1): { frame: number } {
    const run = (t: number) => {
      const values = bandValuesAt(t);
      const weights = state.prepared.map((prepared) => weightsFor(prepared, values));
      if (state.deformer!.useCPU) weights.forEach((w) => deformCPU(state.basis!, w, cpuBuffer()));
      else state.deformer!.computePositions(weights);
      finish();
    };
    run(t0);
    const start = performance.now();
    for (let i = 0; i < count; i++) run(t0 + 0.1 * i);
    return { frame: (performance.now() - start) / count };
  },
  /** Time one frame's deformation + draw of every tile (ms), for benchmarks. */
  timeFrames(count: number, t0 = 1): { frame: number } {
    drawFrame(t0); finish();
    const start = performance.now();
    for (let i = 0; i < count; i++) { drawFrame(t0 + 0.1 * i); finish(); }
    return { frame: (performance.now() - start) / count };
  },
};
(window as any).eigendance = hooks;

let started = false;

/** Load the first mesh and song and show the gallery (at start, or once uploads complete the
 * library). Returns false while the library lacks a mesh or a song. */
async function loadFirst(library: api.Library): Promise<boolean> {
  if (!library.meshes.length || !library.songs.length) {
    status(`the library needs ${library.meshes.length ? "a song" : "a mesh"}: drop files here`);
    return false;
  }
  const meshId = params.get("mesh") ?? library.meshes[0].id;
  const songId = params.get("song") ?? library.songs[0].id;
  $<HTMLSelectElement>("size").value = String(state.size);
  await loadSong(songId);
  await loadMesh(meshId);
  await newGallery();
  const mappingId = params.get("mapping");
  if (mappingId) {
    state.playerMapping = await api.getJSON<Mapping>(`api/mappings/${mappingId}`);
    state.playerPrepared = prepare(state.playerMapping, state.basis!.k);
  }
  setView(state.view);
  choosePath();
  drawFrame(now());
  updatePlayerInfo();
  status(renderMode ? "render mode" : "ready: press ▶ or space");
  started = true;
  return true;
}

async function start(): Promise<void> {
  // ?bare: only the canvas (offline video frames); ?render: time set by renderAt(t).
  document.body.classList.toggle("bare", params.has("bare"));
  wireControls();
  if (!renderMode) requestAnimationFrame(loop);
  await loadFirst(await refreshLibrary());
}

hooks.ready = start().catch((error) => {
  status(`error: ${(error as Error).message}`);
  throw error;
});
