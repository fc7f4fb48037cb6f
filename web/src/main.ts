// eigendance web app: an animated gallery and a live player, in sync with the music
// (docs/design.md#gallery, #rendering). Entry only: read the URL options, start the App, and put the test / offline
// rendering hooks on `window.eigendance` when `?render` or `?test` asks for them.
import { App } from "./app";
import { installHooks } from "./hooks";
import { readOptions, wantsHooks } from "./options";
import "./style.css";

import { isOutputPage, startControl, startOutput } from "./show-start";

const options = readOptions(location.search);
if (isOutputPage(location.pathname)) {
  void startOutput(options, wantsHooks(options) ? installHooks : null);
} else {
  const app = new App(options);
  const ready = app.start();
  if (wantsHooks(options)) installHooks(app, ready);
  startControl(app);
}
