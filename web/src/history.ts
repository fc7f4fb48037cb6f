// The gallery's history as a tree (docs/web.md#gallery): every generation ever shown is kept; a
// generation bred from an earlier one starts a branch instead of replacing what came after it.
// Pure, so Vitest checks it without a browser.

export interface Generation<T> {
  mappings: T[];
  /** index of the generation it was bred from; null for a first (initial) generation */
  parent: number | null;
  /** what a first generation was made for (mesh and song) */
  note: string;
}

/** One line of the generations menu, in tree order (children after their parent). */
export interface Entry { index: number; depth: number; label: string; }

export class History<T> {
  readonly generations: Generation<T>[] = [];
  /** the generation on screen (−1: none yet) */
  current = -1;

  get size(): number { return this.generations.length; }

  get shown(): Generation<T> | null { return this.generations[this.current] ?? null; }

  /** Add a generation (bred from `parent`, or a first one with parent null) and show it. */
  add(mappings: T[], parent: number | null, note = ""): number {
    this.generations.push({ mappings, parent, note });
    this.current = this.generations.length - 1;
    return this.current;
  }

  /** Every generation in tree order: a first generation, then its descendants depth first. */
  entries(): Entry[] {
    const children = new Map<number | null, number[]>();
    this.generations.forEach((g, i) => {
      children.set(g.parent, [...(children.get(g.parent) ?? []), i]);
    });
    const out: Entry[] = [];
    const visit = (index: number, depth: number) => {
      const g = this.generations[index];
      const what = g.parent === null ? `first${g.note ? ` · ${g.note}` : ""}`
        : `bred from ${g.parent + 1}`;
      out.push({ index, depth, label: `${"  ".repeat(depth)}${depth ? "└ " : ""}`
        + `${index + 1} · ${what}` });
      for (const child of children.get(index) ?? []) visit(child, depth + 1);
    };
    for (const root of children.get(null) ?? []) visit(root, 0);
    return out;
  }

  /** The generation `step` places before (−1) or after (+1) the current one in tree order;
   * the current one at either end. */
  neighbour(step: -1 | 1): number {
    const order = this.entries().map((entry) => entry.index);
    const at = order.indexOf(this.current);
    return order[Math.max(0, Math.min(order.length - 1, at + step))] ?? this.current;
  }
}
