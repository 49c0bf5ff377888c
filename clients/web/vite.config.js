// `npm run build -- --outDir DIR` makes the files radiantd serves (CMake puts them in
// share/radiant/web). Relative asset paths, so the viewer also works under a path prefix.
import { defineConfig } from "vite";

export default defineConfig({
    base: "./",
    build: { emptyOutDir: true, chunkSizeWarningLimit: 1024 },
    // `npm run dev`: the viewer with live reload, talking to a radiantd on its default address.
    server: { proxy: { "/v1": "http://127.0.0.1:8080" } },
});
