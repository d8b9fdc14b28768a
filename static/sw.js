// Schwenkbar's service worker: offline after one visit (issue 12).
// This file is a template. `build_pages` (scripts/env.sh) runs scripts/precache.py after trunk,
// which writes dist/sw.js with VERSION (a hash of every file in dist/) and PRECACHE (every file
// in dist/: both pages, the wasm, the JS glue, CSS, manifest, icons). trunk itself does not ship
// this file, so `trunk serve` has no service worker (the registration just fails, quietly).
//
// A new build changes VERSION, so the browser sees a new sw.js at the next visit: it installs
// the new build into a new cache, takes over at once and deletes the old caches on activate.
// The cache always holds exactly one complete build; nothing is added to it at run time.
"use strict";

const VERSION = "dev";
const PRECACHE = [];

const PREFIX = "schwenkbar-";
const CACHE = PREFIX + VERSION;
// How long a page request may wait for the server before the cached page is shown.
const NAVIGATION_TIMEOUT_MS = 4000;

self.addEventListener("install", (event) => {
  event.waitUntil(
    caches
      .open(CACHE)
      // cache: "reload" skips the browser's HTTP cache, so the cache gets this build's bytes.
      .then((cache) => cache.addAll(PRECACHE.map((url) => new Request(url, { cache: "reload" }))))
      .then(() => self.skipWaiting()),
  );
});

self.addEventListener("activate", (event) => {
  event.waitUntil(
    caches
      .keys()
      .then((keys) => Promise.all(keys.filter((k) => k.startsWith(PREFIX) && k !== CACHE).map((k) => caches.delete(k))))
      .then(() => self.clients.claim()),
  );
});

self.addEventListener("fetch", (event) => {
  const request = event.request;
  if (request.method !== "GET" || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith(request.mode === "navigate" ? page(request) : asset(request));
});

// Pages: network first, the cache when the network fails or is slow. The pages name the
// build's hashed wasm/JS/CSS files, so the freshest page is the one to show whenever the server
// answers: a new build (scripts/serve.sh, `trunk serve` on the same port) shows at once instead
// of one visit later, as it would with cache-first. Offline the fetch fails at once and the
// cached page of the installed build comes up, and with it that build's cached assets.
async function page(request) {
  const network = fetch(request);
  network.catch(() => {}); // answered below; no unhandled rejection when the cache wins
  let timer;
  const timeout = new Promise((resolve) => {
    timer = setTimeout(resolve, NAVIGATION_TIMEOUT_MS, null);
  });
  try {
    const response = await Promise.race([network, timeout]);
    if (response) return response;
  } catch (_) {
    // offline or the server is gone: the cache below
  } finally {
    clearTimeout(timer);
  }
  const cached = await cachedPage(request);
  return cached || network; // nothing cached: the network's answer or error, as without us
}

async function cachedPage(request) {
  const cache = await caches.open(CACHE);
  const url = new URL(request.url);
  url.search = "";
  url.hash = "";
  if (url.pathname.endsWith("/")) url.pathname += "index.html";
  return cache.match(url.href);
}

// Everything else (hashed wasm/JS/CSS, manifest, icons): cache first, else the network.
async function asset(request) {
  const cache = await caches.open(CACHE);
  return (await cache.match(request, { ignoreSearch: true })) || fetch(request);
}
