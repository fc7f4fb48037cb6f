// The page's keys, in one table that binds them and writes the help's rows (the show's keys,
// show-control.ts, join the help the same way; test/keys.test.ts: no key is bound twice). They
// work whatever has the focus — a slider, a button, a menu just used — except where one types
// (a number or text field).

/** A row of keys: the keys (`KeyboardEvent.key`, a letter in lower case) and what they do. */
export type KeyRow = readonly [keys: readonly string[], what: string];

/** The page's keys; `Home` is left to a focused slider (it moves the slider there). */
export const PAGE_KEYS = [
  [[" "], "play / pause"], [["Home"], "back to 0:00"],
  [["g", "p"], "gallery, player"], [["b"], "breed the selected tiles"],
  [["[", "]"], "previous, next generation"], [["m"], "mute"],
  [["l"], "loop the song"], [["f"], "full screen"],
  [["r"], "reset the player's view"], [["?", "h"], "this help"], [["Escape"], "close"],
] as const satisfies readonly KeyRow[];

export type PageKey = (typeof PAGE_KEYS)[number][0][number];

/** What each of the page's keys does. */
export type KeyActions = Record<PageKey, () => void>;

/** The key of a keydown as the tables name it (a letter in lower case). */
export function keyName(e: KeyboardEvent): string {
  return e.key.length === 1 ? e.key.toLowerCase() : e.key;
}

/** Whether a keydown is the page's to take: no modifier, and not where one types. */
export function forThePage(e: KeyboardEvent): boolean {
  if (e.ctrlKey || e.metaKey || e.altKey) return false;
  const target = e.target as HTMLElement;
  const typing = target instanceof HTMLTextAreaElement || (target instanceof HTMLInputElement
    && !["range", "checkbox", "button", "file", "radio"].includes(target.type));
  const slider = target instanceof HTMLInputElement && target.type === "range";
  return !typing && !(slider && e.key === "Home");
}

export function wireKeys(actions: KeyActions): void {
  addKeysToHelp(PAGE_KEYS);
  // A menu keeps the focus after a choice and would take the next letters for itself.
  document.querySelectorAll("select").forEach((menu) => {
    menu.addEventListener("change", () => menu.blur());
  });
  window.addEventListener("keydown", (e) => {
    if (!forThePage(e)) return;
    const action = (actions as Record<string, () => void>)[keyName(e)];
    if (!action) return;
    e.preventDefault(); // a focused button would also be clicked by space
    action();
  });
}

/** How the help writes a key: `space`, `G`, `PageDown`; a run of keys as its ends (1–9). */
function shown(keys: readonly string[]): string {
  const kbd = (key: string) => `<kbd>${key === " " ? "space" : key === "Escape" ? "Esc"
    : key.length === 1 ? key.toUpperCase() : key}</kbd>`;
  return keys.length > 2 ? `${kbd(keys[0])}–${kbd(keys[keys.length - 1])}`
    : keys.map(kbd).join(" ");
}

/** The rows' keys at the end of the help's table of keys. */
export function addKeysToHelp(rows: readonly KeyRow[]): void {
  const table = document.querySelector("#help table");
  if (!table) return;
  for (const [keys, what] of rows) {
    const row = document.createElement("tr");
    row.innerHTML = `<td>${shown(keys)}</td><td></td>`;
    row.cells[1].textContent = what;
    table.append(row);
  }
}
