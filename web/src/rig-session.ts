// The rigs' part of the session (session.ts, issue 30): per rig, its dances' generations, the one
// shown, the dances selected and the player's mapping with its palette — kept in the browser
// after every change, so that a reload (or *open session*) shows them again when the rig opens (restoreSession brings them).
import type { SavedRig } from "./session";
import { keepInSession } from "./session";

export class RigSessions {
  private readonly saved = new Map<string, SavedRig>();

  /** Rigs of a saved session, in place of these rigs' (others stay). */
  restore(rigs: Record<string, SavedRig>): void {
    for (const [id, rig] of Object.entries(rigs)) this.saved.set(id, rig);
  }

  get(id: string): SavedRig | undefined { return this.saved.get(id); }

  /** Forget rig `id` (removed from the library on purpose). */
  forget(id: string): void { this.saved.delete(id); }

  /** Keep rig `id`'s galleries (in the browser too). */
  set(id: string, rig: SavedRig): void {
    this.saved.set(id, structuredClone(rig));
    keepInSession({ rigs: this.snapshot() });
  }

  snapshot(): Record<string, SavedRig> { return Object.fromEntries(this.saved); }
}
