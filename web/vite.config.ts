import { defineConfig } from "vite";

// The build goes into the Python package, so a wheel serves it without Node.
export default defineConfig({
  base: "./",
  build: {
    outDir: "../src/eigendance/static",
    emptyOutDir: true,
    chunkSizeWarningLimit: 1000,
    // Stable names: the built app is committed, so a wheel needs no Node.
    rollupOptions: {
      output: {
        entryFileNames: "assets/app.js",
        chunkFileNames: "assets/[name].js",
        assetFileNames: "assets/[name][extname]",
      },
    },
  },
  // The live input's AudioWorklet (web/src/live-worklet.ts) is built as its own module.
  worker: {
    format: "es",
    rollupOptions: { output: { entryFileNames: "assets/[name].js" } },
  },
  test: {
    include: ["test/**/*.test.ts"],
  },
} as any);
