// The header's controls: the library menus and their ✕ (remove), play / pause and the position,
// volume and mute, the gallery / player tabs and the *tiles* menu; and the keys, which do what
// these controls do.
import * as api from "./api";
import type { App } from "./app";
import { $, fileName, saveJSON } from "./dom";
import type { Mapping } from "./filter";
import { wireKeys } from "./keys";
import { choiceOf } from "./live-source";
import { forgetInSession, keepInSession, matched, modelOf, named, readSession, restoreSession, resumeModel,
  resumeSong, sessionOf, songOf } from "./session";

export function wireHeader(app: App): void {
  const valueOf = (event: Event) => (event.target as HTMLInputElement | HTMLSelectElement).value;
  const { messages, transport, viewer, library } = app;
  $("mesh").addEventListener("change", (e) => {
    const meshId = valueOf(e);
    if (meshId.startsWith("rig:")) { void app.openRig(meshId.slice(4)); return; }
    void messages.guard("Could not show this model", async () => {
      if (!(await app.showMesh(meshId))) messages.status("");
    });
  });
  $("song").addEventListener("change", (e) => {
    const songId = valueOf(e);
    const live = choiceOf(songId);
    if (live) { void app.startLive(live); return; }
    void messages.guard("Could not play this song", () => app.changeSong(songId));
  });
  $("mapping-menu").addEventListener("change", (e) => {
    const id = valueOf(e);
    const name = library.mappings.find((m) => m.id === id)?.name ?? "mapping";
    void messages.guard(`Could not open ${name}`, async () => {
      app.open(await api.getJSON<Mapping>(`api/mappings/${id}`), name);
    });
  });
  for (const kind of ["mesh", "song", "mapping"] as const) {
    $(`remove-${kind}`).addEventListener("click", () => void remove(app, kind));
  }
  $("play").addEventListener("click", () => app.togglePlay());
  $("seek").addEventListener("input", (e) => {
    transport.seek(Number(valueOf(e)));
    viewer.requestDraw();
  });
  const volume = $<HTMLInputElement>("volume");
  volume.addEventListener("input", () => {
    transport.volume = Number(volume.value);
    if (transport.muted) toggleMute(app);
  });
  $("mute").addEventListener("click", () => toggleMute(app));
  $("loop").addEventListener("click", () => toggleLoop(app));
  // A song that stops at its end says so (choosing a rig or a view then does not look like the
  // cause); the hint goes when ▶ plays it again.
  transport.onEnd = () => messages.hint("the song ended: ▶ plays it again (↻ repeats it)", false);
  for (const id of ["save-session", "rig-save-session"]) { // the harmonics' and a rig's bar
    $(id).addEventListener("click", () => void messages.guard("Could not save the session",
      async () => {
        const session = sessionOf(app.gallery.snapshot(), app.rigs.sessions.snapshot(),
          songOf(app), modelOf(app));
        await library.refresh(); // the names, found by name by a server run again
        saveJSON(named(session), fileName(app.rigs.active ? app.rigs.rig?.name ?? ""
          : app.library.meshName, "session", "json"));
      }));
  }
  for (const id of ["open-session", "rig-open-session"]) {
    $(id).addEventListener("change", (e) => {
      const input = e.target as HTMLInputElement;
      const file = input.files?.[0];
      input.value = "";
      if (!file) return;
      void messages.guard(`Could not open ${file.name}`, async () => {
        // The song first: choosing it calibrates a new first generation, which the file replaces.
        const held = await library.refresh();
        const read = readSession(await file.text());
        const match = matched(read, held); // ids of another run found by name
        await resumeSong(app, match.session.song, held);
        const line = restoreSession(app, match, read); // as a reload restores the stored one
        if (!app.rigs.active) app.gallery.showMesh(library.meshId);
        await resumeModel(app, match.session.model, held); // the model it was saved on
        keepInSession({ song: songOf(app), model: modelOf(app) }); // the song now playing
        messages.status(`${file.name}: ${line}`);
      });
    });
  }
  // The song chosen, where it plays and the model on screen stay in the session: a reload
  // comes back to them.
  window.addEventListener("pagehide",
    () => keepInSession({ song: songOf(app), model: modelOf(app) }));
  for (const id of ["reset-view", "rig-reset-view"]) {
    $(id).addEventListener("click", () => resetView(app));
  }
  $("tab-gallery").addEventListener("click", () => app.setView("gallery"));
  $("tab-player").addEventListener("click", () => app.setView("player"));
  const sizes = $<HTMLSelectElement>("size");
  sizes.addEventListener("change", () => void app.newGallery(Number(sizes.value)));
  window.addEventListener("resize", () => {
    viewer.resetPlayerCamera();
    viewer.requestDraw();
  });
  // A banner or a wrapped header moves the views: draw again where they are now.
  new ResizeObserver(() => viewer.requestDraw()).observe($("tiles"));
  new ResizeObserver(() => viewer.requestDraw()).observe($("player-area"));
  wireKeys({
    " ": () => app.togglePlay(),
    g: () => app.setView("gallery"),
    p: () => app.setView("player"),
    b: () => {
      void messages.guard("Breeding failed",
        () => (app.rigs.active ? app.rigs.gallery.breed() : app.gallery.breed()));
    },
    "[": () => app.gallery.step(-1),
    "]": () => app.gallery.step(1),
    m: () => toggleMute(app),
    l: () => toggleLoop(app),
    r: () => resetView(app),
    f: () => toggleFullScreen(),
    "?": () => messages.help($("help").hidden),
    h: () => messages.help($("help").hidden),
    Escape: () => { messages.help(false); messages.clearError(); },
    Home: () => { transport.seek(0); viewer.requestDraw(); },
  });
}

function toggleLoop(app: App): void {
  app.transport.loop = !app.transport.loop;
  $("loop").setAttribute("aria-pressed", String(app.transport.loop));
  $("loop").classList.toggle("on", app.transport.loop);
}

/** The player's camera back to the whole model (after turning or zooming it). */
function resetView(app: App): void {
  app.shownViewer().resetPlayerCamera();
}

/** The page in full screen, or back (Esc works too). */
function toggleFullScreen(): void {
  if (document.fullscreenElement) void document.exitFullscreen();
  else void document.documentElement.requestFullscreen?.().catch(() => {});
}

function toggleMute(app: App): void {
  app.transport.muted = !app.transport.muted;
  $("mute").classList.toggle("muted", app.transport.muted);
}

/** Remove the item chosen in `kind`'s menu from the server's library (not from the disk);
 * a removed model or song on screen gives way to the first one left. */
async function remove(app: App, kind: "mesh" | "song" | "mapping"): Promise<void> {
  const menu = $<HTMLSelectElement>(kind === "mapping" ? "mapping-menu" : kind);
  const rig = kind === "mesh" && menu.value.startsWith("rig:"); // the model menu lists rigs too
  if (kind === "song" && choiceOf(menu.value)) {
    app.messages.status("a live input plays: choose a song in the menu to remove it");
    return;
  }
  const id = rig ? menu.value.slice(4) : menu.value;
  const name = menu.selectedOptions[0]?.textContent ?? `the ${kind}`;
  await app.messages.guard(`Could not remove ${name}`, async () => {
    if (kind === "mesh") app.library.drop(id); // its harmonics may be computing
    await api.remove(rig ? "rig" : kind, id);
    forgetInSession(app, id); // removed on purpose: a reload does not miss it
    const library = await app.library.refresh();
    if (rig || (kind === "mesh" && id === app.library.meshId)) {
      const next = library.meshes.find((m) => m.id === app.library.meshId) ?? library.meshes[0];
      if (next) await app.showMesh(next.id); // leaves the rig's views
    } else if (kind === "song" && id === app.library.songId && library.songs.length) {
      app.transport.pause();
      await app.changeSong(library.songs[0].id);
    }
    app.messages.status(`${name} removed from the library`);
  });
}
