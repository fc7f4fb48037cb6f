// The session (issue 30): every model's gallery history — its generations, the one on screen and
// the tiles selected — and every rig's (its dances' generations, the one shown, the dances
// selected, and the player's mapping with its palette), kept in the browser's storage, so that a
// reload shows them again, and written to a file (*save session*) that *open session* reads
// back. Pure but for the storage.
import type { Mapping } from "./filter";
import type { Generation } from "./history";

export const SESSION_FORMAT = "eigendance.session";
const KEY = "eigendance-session";

/** One model's gallery history as saved. */
export interface SavedHistory { generations: Generation<Mapping>[]; current: number;
  selected: number[]; }

/** One rig's galleries as saved: its dances' generations, the one shown and the dances selected,
 * and what its player plays (the mapping with its palette, as *save mapping* writes it). */
export interface SavedRig { generations: Mapping[][]; generation: number; selected: number[];
  player: { mapping: Mapping; source: string } | null; }

/** The session file: the gallery history of each model and the galleries of each rig (by the
 * library's ids). */
export interface Session { format: string; version: 1; histories: Record<string, SavedHistory>;
  rigs?: Record<string, SavedRig>; }

export function sessionOf(histories: Record<string, SavedHistory>,
                          rigs: Record<string, SavedRig> = {}): Session {
  return { format: SESSION_FORMAT, version: 1, histories, rigs };
}

/** Keep one part of the session in the browser, the other as it is kept. */
export function keepInSession(part: { histories?: Record<string, SavedHistory>;
  rigs?: Record<string, SavedRig> }): void {
  const kept = storedSession();
  storeSession(sessionOf(part.histories ?? kept?.histories ?? {}, part.rigs ?? kept?.rigs ?? {}));
}

/** A session file's text checked; throws one line saying what is wrong. */
export function readSession(text: string): Session {
  let data: unknown;
  try { data = JSON.parse(text); } catch { throw new Error("this file is not JSON"); }
  const session = data as Session;
  if (!session || session.format !== SESSION_FORMAT || typeof session.histories !== "object"
      || session.histories === null) {
    throw new Error(`this file is not an eigendance session (format "${SESSION_FORMAT}")`);
  }
  for (const [id, history] of Object.entries(session.histories)) {
    if (!Array.isArray(history?.generations) || !history.generations.every(
      (g) => Array.isArray(g?.mappings) && g.mappings.every((m) => Array.isArray(m?.transfer)))) {
      throw new Error(`the gallery of model ${id} in this session is not readable`);
    }
  }
  for (const [id, rig] of Object.entries(session.rigs ?? {})) {
    if (!Array.isArray(rig?.generations) || !rig.generations.every((g) => Array.isArray(g)
      && g.every((m) => Array.isArray(m?.transfer))) || !Array.isArray(rig.selected)) {
      throw new Error(`the galleries of rig ${id} in this session are not readable`);
    }
  }
  return session;
}

/** Keep the session in the browser (nothing is said when storage is off or full). */
export function storeSession(session: Session): void {
  try { localStorage.setItem(KEY, JSON.stringify(session)); } catch { /* private mode, full */ }
}

/** The session kept in the browser, or null. */
export function storedSession(): Session | null {
  try {
    const text = localStorage.getItem(KEY);
    return text ? readSession(text) : null;
  } catch {
    return null;
  }
}
