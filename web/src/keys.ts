// The page's keys (the help lists them). They work whatever has the focus — a slider, a button,
// a menu just used — except where one types (a number or text field).

/** What each key does; `Home` is left to a focused slider (it moves the slider there). */
export type KeyActions = Record<string, () => void>;

export function wireKeys(actions: KeyActions): void {
  // A menu keeps the focus after a choice and would take the next letters for itself.
  document.querySelectorAll("select").forEach((menu) => {
    menu.addEventListener("change", () => menu.blur());
  });
  window.addEventListener("keydown", (e) => {
    if (e.ctrlKey || e.metaKey || e.altKey) return;
    const target = e.target as HTMLElement;
    const typing = target instanceof HTMLTextAreaElement || (target instanceof HTMLInputElement
      && !["range", "checkbox", "button", "file", "radio"].includes(target.type));
    const slider = target instanceof HTMLInputElement && target.type === "range";
    if (typing || (slider && e.key === "Home")) return;
    const action = actions[e.key.length === 1 ? e.key.toLowerCase() : e.key] ?? actions[e.key];
    if (!action) return;
    e.preventDefault(); // a focused button would also be clicked by space
    action();
  });
}
