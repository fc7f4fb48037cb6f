// Small DOM helpers shared by the views.

/** The element with this id; the page's markup (index.html) guarantees it exists. */
export function $<T extends HTMLElement = HTMLElement>(id: string): T {
  return document.getElementById(id) as T;
}

/** Offer `blob` as a download named `name`. */
export function saveBlob(blob: Blob, name: string): void {
  const link = document.createElement("a");
  link.href = URL.createObjectURL(blob);
  link.download = name;
  link.click();
  setTimeout(() => URL.revokeObjectURL(link.href), 1000);
}

/** A file name's part from a model's name and what it is: `fileName("cat.obj", "tile 3",
 * "json")` is `cat-tile-3.json` (letters, digits, _ and -, and dots in `what`; "dance" without a name). */
export function fileName(model: string, what: string, suffix: string): string {
  const slug = (text: string, keep: RegExp) => text.replace(keep, "-").replace(/^-+|-+$/g, "");
  const stem = slug(model.replace(/\.[^.]*$/, ""), /[^\w-]+/g) || "dance";
  return `${[stem, slug(what, /[^\w.-]+/g)].filter(Boolean).join("-")}.${suffix}`;
}

/** Offer a JSON document (a mapping) as a download. */
export function saveJSON(data: unknown, name: string): void {
  saveBlob(new Blob([JSON.stringify(data, null, 1)], { type: "application/json" }), name);
}

/** The message of anything thrown (an Error from the API carries the server's message). */
export function messageOf(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}
