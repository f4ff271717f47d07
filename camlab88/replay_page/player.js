"use strict";
// The replay page's player: the session's frames as a video, seek by scrubber, timeline and
// list rows, speed 0.25-8x, frame steps, the emulator's keys (F5 pause, F6 step, F7/F8).
// Frame k of the video is shown at currentTime (k + 0.5) / fps; D.frames[i] = [first video
// frame of shown frame i, its virtual time], so shown frames map both ways.
(function () {
  const D = JSON.parse(document.getElementById("data").textContent);
  const video = document.getElementById("video");
  const $ = (id) => document.getElementById(id);
  const play = $("play"), scrub = $("scrub"), speedSel = $("speed"), status = $("status");
  const timeline = $("timeline"), marks = $("marks"), head = $("head"), announce = $("announce");
  const SPEEDS = [0.25, 0.5, 1, 2, 4, 8];
  const fps = D.fps, frames = D.frames, n = frames.length;
  const total = Math.max(1, D.videoFrames);
  let shown = -1, speed = 1;

  // ---------------------------------------------------------------- the video's source
  // Inlined: decoded into a Blob. Beside the page on a web server: fetched whole into a
  // Blob too, so seeking works on servers without range requests (python -m http.server);
  // from file:// (where fetch is refused) the file is the source.
  const inline = document.getElementById("video-data");
  if (inline) {  // the browser's own base64 decoder (a data: URL), into a Blob
    fetch(`data:${inline.dataset.mime};base64,${inline.textContent.trim()}`)
      .then((r) => r.blob())
      .then((b) => { video.src = URL.createObjectURL(b); });
  } else if (location.protocol === "http:" || location.protocol === "https:") {
    fetch(video.dataset.src)
      .then((r) => { if (!r.ok) throw new Error(r.statusText); return r.blob(); })
      .then((b) => { video.src = URL.createObjectURL(b); })
      .catch(() => { video.src = video.dataset.src; });
  } else {
    video.src = video.dataset.src;
  }

  // ---------------------------------------------------------------- time <-> frames
  function lastAtMost(rows, value, key) {  // index of the last row with key(row) <= value
    let lo = 0, hi = rows.length - 1, ans = -1;
    while (lo <= hi) {
      const mid = (lo + hi) >> 1;
      if (key(rows[mid]) <= value) { ans = mid; lo = mid + 1; } else { hi = mid - 1; }
    }
    return ans;
  }
  const shownAtVideoFrame = (k) => Math.max(0, lastAtMost(frames, k, (r) => r[0]));
  function shownAtOrAfter(t) {  // the first frame shown at or after virtual time t
    const i = lastAtMost(frames, t - 1e-9, (r) => r[1]) + 1;
    return Math.min(n - 1, i);
  }
  const videoFrameNow = () => Math.min(total - 1, Math.floor(video.currentTime * fps + 1e-6));
  function goToShown(i, why) {
    i = Math.max(0, Math.min(n - 1, i));
    video.currentTime = (frames[i][0] + 0.5) / fps;
    show(i);
    if (why) say(why);
  }
  const goToTime = (t, why) => goToShown(shownAtOrAfter(t), why);

  // ---------------------------------------------------------------- lists
  function fill(list, rows, text, time) {
    const frag = document.createDocumentFragment();
    rows.forEach((row, i) => {
      const li = document.createElement("li");
      const b = document.createElement("button");
      b.type = "button";
      b.textContent = text(row);
      b.dataset.i = i;
      if (row[3]) li.className = "warn";
      li.appendChild(b);
      frag.appendChild(li);
    });
    list.appendChild(frag);
    list.addEventListener("click", (e) => {
      const b = e.target.closest("button");
      if (!b) return;
      pause();
      const row = rows[+b.dataset.i];
      goToTime(time(row), b.textContent);
      mark(list, rows, time, +b.dataset.i);
    });
  }
  const t3 = (t) => t.toFixed(3).padStart(8);
  const events = $("events"), orders = $("orders");
  fill(events, D.events, (r) => `${t3(r[0])} s  ${r[1]}`, (r) => r[0]);
  fill(orders, D.orders, (r) => `${String(r[0]).padStart(7)}  ${t3(r[1])} s  ${r[2]}`,
       (r) => r[1]);
  if (!D.events.length) {
    events.insertAdjacentHTML("beforeend",
      "<li>none: no input reached the program through the harness</li>");
  }

  const marked = new Map();  // list -> its highlighted rows
  function mark(list, rows, time, current, from) {
    for (const li of marked.get(list) || []) li.classList.remove("current", "now");
    const lit = [];
    if (current >= 0) {
      const start = Math.max(from === undefined ? current : from, current - 200);
      for (let i = start; i <= current; i++) {
        const li = list.children[i];
        li.classList.add(i === current ? "current" : "now");
        lit.push(li);
      }
      const li = list.children[current];
      const top = li.offsetTop - list.offsetTop;
      if (top < list.scrollTop || top > list.scrollTop + list.clientHeight - li.offsetHeight) {
        list.scrollTop = top - list.clientHeight / 2;
      }
    }
    marked.set(list, lit);
  }
  function markLists(i) {
    const t = frames[i][1], before = i > 0 ? frames[i - 1][1] : -Infinity;
    const ev = lastAtMost(D.events, t, (r) => r[0]);
    mark(events, D.events, (r) => r[0], ev);
    if (D.orders.length) {  // the orders drawn for this frame: after the previous frame's time
      const last = lastAtMost(D.orders, t, (r) => r[1]);
      const first = lastAtMost(D.orders, before, (r) => r[1]) + 1;
      mark(orders, D.orders, (r) => r[1], last, Math.min(first, last));
    }
  }

  // ---------------------------------------------------------------- what is shown
  function show(i) {
    if (i === shown) return;
    shown = i;
    scrub.value = i;
    const text = `frame ${i + 1} of ${n}, t = ${frames[i][1].toFixed(3)} s`;
    scrub.setAttribute("aria-valuetext", text);
    timeline.setAttribute("aria-valuenow", i);
    timeline.setAttribute("aria-valuetext", text);
    status.textContent = `${text} · ${speed}× · ${video.paused ? "paused" : "playing"}`;
    status.dataset.frame = i;
    status.dataset.time = frames[i][1];
    head.style.left = `${(100 * (frames[i][0] + 0.5)) / total}%`;
    markLists(i);
  }
  function refresh() {
    shown = -1;
    show(shownAtVideoFrame(videoFrameNow()));
  }
  function tick() {
    show(shownAtVideoFrame(videoFrameNow()));
    if (!video.paused) requestAnimationFrame(tick);
  }
  const say = (text) => { announce.textContent = text; };

  // ---------------------------------------------------------------- controls
  function playPause() {
    if (video.paused) {
      if (video.ended || videoFrameNow() >= total - 1) video.currentTime = 0;
      video.play();
    } else {
      pause();
    }
  }
  function pause() { if (!video.paused) video.pause(); }
  function setSpeed(s) {
    speed = Math.min(8, Math.max(0.25, s));
    video.playbackRate = speed;
    speedSel.value = String(speed);
    say(`speed ${speed}×`);
    refresh();
  }
  function step(by) {
    pause();
    goToShown(shownAtVideoFrame(videoFrameNow()) + by);
  }
  video.addEventListener("play", () => {
    play.textContent = "Pause";
    play.setAttribute("aria-label", "Pause");
    refresh();
    requestAnimationFrame(tick);
  });
  video.addEventListener("pause", () => {
    play.textContent = "Play";
    play.setAttribute("aria-label", "Play");
    refresh();
  });
  video.addEventListener("seeked", refresh);
  video.addEventListener("ended", refresh);
  play.addEventListener("click", playPause);
  $("step").addEventListener("click", () => step(1));
  $("back").addEventListener("click", () => step(-1));
  $("slower").addEventListener("click", () => setSpeed(speed / 2));
  $("faster").addEventListener("click", () => setSpeed(speed * 2));
  speedSel.addEventListener("change", () => setSpeed(+speedSel.value));
  scrub.max = n - 1;
  timeline.setAttribute("aria-valuemax", n - 1);
  scrub.addEventListener("input", () => { pause(); goToShown(+scrub.value); });
  timeline.addEventListener("click", (e) => {
    const box = timeline.getBoundingClientRect();
    const k = Math.floor(((e.clientX - box.left) / box.width) * total);
    pause();
    goToShown(shownAtVideoFrame(Math.max(0, Math.min(total - 1, k))));
  });

  document.addEventListener("keydown", (e) => {
    if (e.altKey || e.ctrlKey || e.metaKey) return;
    const t = e.target, tag = t && t.tagName;
    const own = tag === "INPUT" || tag === "SELECT";  // they answer arrows themselves
    const i = shownAtVideoFrame(videoFrameNow());
    let done = true;
    switch (e.key) {
      case "F5": playPause(); break;
      case " ":
        if (tag === "BUTTON" || tag === "SELECT" || tag === "SUMMARY") return;
        playPause(); break;
      case "F6": case ".": step(1); break;
      case ",": step(-1); break;
      case "F7": setSpeed(speed / 2); break;
      case "F8": setSpeed(speed * 2); break;
      case "ArrowRight": if (own) return; pause(); goToTime(frames[i][1] + 1); break;
      case "ArrowLeft": if (own) return; pause(); goToTime(frames[i][1] - 1); break;
      case "Home": if (own) return; pause(); goToShown(0); break;
      case "End": if (own) return; pause(); goToShown(n - 1); break;
      default: done = false;
    }
    if (done) e.preventDefault();  // F5 would reload the page, F7 toggle caret browsing
  });

  // ---------------------------------------------------------------- the timeline's marks
  function drawMarks() {
    const w = Math.max(1, Math.round(marks.clientWidth * devicePixelRatio));
    marks.width = w;
    marks.height = 36 * devicePixelRatio;
    const g = marks.getContext("2d");
    g.scale(devicePixelRatio, devicePixelRatio);
    const cw = marks.clientWidth;
    const x = (t) => ((frames[shownAtOrAfter(t)][0] + 0.5) / total) * cw;
    g.fillStyle = "#c05000";
    for (const r of D.events) g.fillRect(x(r[0]), 2, 1, 14);
    const bins = new Array(Math.max(1, Math.floor(cw))).fill(0);
    for (const r of D.orders) bins[Math.min(bins.length - 1, Math.floor(x(r[1])))]++;
    const most = Math.max(1, ...bins);
    g.fillStyle = "#3070c0";
    bins.forEach((c, k) => { if (c) g.fillRect(k, 34 - (16 * c) / most, 1, (16 * c) / most); });
  }
  new ResizeObserver(drawMarks).observe(marks);
  video.addEventListener("loadeddata", () => { if (shown < 0) goToShown(0); else refresh(); });
  show(0);
})();
