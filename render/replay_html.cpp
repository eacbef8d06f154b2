// The run as JSON and the canvas player that draws it (colours from the figures' palette).
#include "render/replay_html.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "render/layers.h"
#include "render/palette.h"
#include "util/c_number.h"

namespace plantsim::render {
namespace {

using geom::Vec2;
using nlohmann::json;

double round_to(double v, double step) { return std::round(v / step) * step; }

json rect(const geom::Rect& r) {
  return {round_to(r.xmin, 1e-3), round_to(r.ymin, 1e-3), round_to(r.xmax, 1e-3),
          round_to(r.ymax, 1e-3)};
}

json points(const std::vector<Vec2>& pts) {
  json out = json::array();
  for (const Vec2& p : pts) out.push_back({round_to(p.x, 1e-3), round_to(p.y, 1e-3)});
  return out;
}

std::string css(Rgb c) {
  char buf[16];
  util::c_snprintf(buf, sizeof buf, "#%02x%02x%02x", c.r, c.g, c.b);
  return buf;
}

/// The episode's events (stops, replans, ...) at their times and places, and its failure: where the
/// replay ends, with the reason, when, where and why.
void add_events_and_failure(json& j, const episode::EpisodeResult& run) {
  j["events"] = json::array();
  for (const auto& e : run.events) {
    using Kind = episode::EpisodeResult::Event::Kind;
    const char* kind = e.kind == Kind::kStop        ? "stop"
                       : e.kind == Kind::kReplan    ? "replan"
                       : e.kind == Kind::kRecovery  ? "recovery"
                       : e.kind == Kind::kCollision ? "collision"
                       : e.kind == Kind::kRetry     ? "retry"
                                                    : "failure";
    j["events"].push_back({{"k", kind},
                           {"t", round_to(e.t_s, 1e-3)},
                           {"x", round_to(e.at.x, 1e-3)},
                           {"y", round_to(e.at.y, 1e-3)}});
  }
  j["failure"] = nullptr;
  if (run.failure)  // where the replay ends: the reason, when, where and why
    j["failure"] = {{"reason", robot::to_string(run.failure->reason)},
                    {"t", round_to(run.failure->time_s, 1e-3)},
                    {"x", round_to(run.failure->pose.x, 1e-3)},
                    {"y", round_to(run.failure->pose.y, 1e-3)},
                    {"detail", run.failure->detail}};
}

/// The trajectory, thinned to the replay's sample limit (the end always kept), and the carries.
void add_trajectory(json& j, const episode::EpisodeResult& run, const ReplayOptions& o) {
  const std::size_t n = run.trajectory.size();
  const std::size_t step =
      std::max<std::size_t>(1, (n + o.max_samples - 1) / std::max(1, o.max_samples));
  json t = json::array(), x = json::array(), y = json::array(), yaw = json::array(),
       v = json::array(), docking = json::array(), ex = json::array(), ey = json::array(),
       sigma = json::array(), health = json::array();
  std::vector<std::size_t> kept;
  for (std::size_t i = 0; i < n; i += step) kept.push_back(i);
  if (n > 0 && kept.back() != n - 1) kept.push_back(n - 1);  // the end, always
  for (std::size_t i : kept) {
    const auto& s = run.trajectory[i];
    t.push_back(round_to(s.t_s, 1e-3));
    x.push_back(round_to(s.truth.x, 1e-4));
    y.push_back(round_to(s.truth.y, 1e-4));
    yaw.push_back(round_to(s.truth.yaw, 1e-4));
    v.push_back(round_to(s.speed_mps, 1e-3));
    docking.push_back(s.phase == controller::DockPhase::kTravel ? 0 : 1);
    ex.push_back(round_to(s.estimate.x, 1e-4));
    ey.push_back(round_to(s.estimate.y, 1e-4));
    sigma.push_back(round_to(s.position_sigma_m, 1e-4));
    health.push_back(static_cast<int>(s.health));
  }
  j["t"] = t;
  j["x"] = x;
  j["y"] = y;
  j["yaw"] = yaw;
  j["v"] = v;
  j["docking"] = docking;
  j["ex"] = ex;
  j["ey"] = ey;
  j["sigma"] = sigma;
  j["health"] = health;  // the estimator's own verdict per frame: 0 ok, 1 degraded, 2 lost
  j["carries"] = json::array();
  for (const auto& c : run.carries)
    j["carries"].push_back({{"t", round_to(c.t_s, 1e-3)},
                            {"from", {round_to(c.from.x, 1e-3), round_to(c.from.y, 1e-3)}},
                            {"to", {round_to(c.to.x, 1e-3), round_to(c.to.y, 1e-3)}}});
}

/// A sampling controller's sketches (its samples and its choice, about once a second), thinned
/// to at most `max_sketches`, to the centimetre.
json sketches(const episode::EpisodeResult& run, std::size_t max_sketches) {
  auto cm = [](const std::vector<Vec2>& pts) {
    json out = json::array();
    for (const Vec2& p : pts) out.push_back({round_to(p.x, 1e-2), round_to(p.y, 1e-2)});
    return out;
  };
  json out = json::array();
  const std::size_t n = run.controller_sketches.size();
  const std::size_t step = std::max<std::size_t>(1, (n + max_sketches - 1) / max_sketches);
  for (std::size_t i = 0; i < n; i += step) {
    const auto& at = run.controller_sketches[i];
    json sampled = json::array();
    for (const auto& trajectory : at.sketch.sampled) sampled.push_back(cm(trajectory));
    out.push_back({{"t", round_to(at.t_s, 1e-3)}, {"s", sampled}, {"c", cm(at.sketch.chosen)}});
  }
  return out;
}

json replay_data(const worlds::World& world, const episode::EpisodeResult& run,
                 const ReplayOptions& o) {
  json j;
  j["world"] = world.name;
  j["floor"] = rect(world.floor);
  j["obstacles"] = json::array();
  for (const auto& r : world.obstacles) j["obstacles"].push_back(rect(r));
  j["unmapped"] = json::array();
  for (const auto& r : world.unmapped) j["unmapped"].push_back(rect(r));
  const worlds::ChargerBody cb = worlds::charger_body(world);
  j["charger"] = {round_to(cb.center.x, 1e-3), round_to(cb.center.y, 1e-3), cb.half_depth_m,
                  cb.half_width_m, cb.yaw};
  j["dock"] = {world.charger.x, world.charger.y};
  j["start"] = {world.start.x, world.start.y};
  j["robot"] = {{"radius", world.robot.radius_m},
                {"length", world.robot.rectangular() ? world.robot.length_m : 0.0},
                {"width", world.robot.rectangular() ? world.robot.width_m : 0.0}};
  j["max_speed"] = world.robot.max_speed_mps;
  j["plan"] = points(run.plan);
  j["first_plan"] =
      run.replans > 0 && run.plan != run.first_plan ? points(run.first_plan) : json::array();
  // The final plan exists from the last replan on; before it the first plan is the one in force.
  double last_replan_s = 0;
  for (const auto& e : run.events)
    if (e.kind == episode::EpisodeResult::Event::Kind::kReplan) last_replan_s = e.t_s;
  j["plan_from_t"] = j["first_plan"].empty() ? 0.0 : round_to(last_replan_s, 1e-3);
  add_trajectory(j, run, o);
  add_events_and_failure(j, run);
  j["sketches"] = sketches(run, 400);
  j["moving_label"] = moving_tracks_label(run.moving_tracks);  // as the run figure's legend
  j["moving"] = json::array();
  for (const auto& track : run.moving_tracks) {
    json m;
    m["t"] = track.t_s;
    m["boxes"] = json::array();
    for (const auto& b : track.boxes) m["boxes"].push_back(rect(b));
    j["moving"].push_back(m);
  }
  j["status"] = episode::status_name(run);
  j["colours"] = {{"floor", css(palette::kFloor)},
                  {"obstacle", css(palette::kObstacle)},
                  {"unmapped", css(palette::kUnmapped)},
                  {"plan", css(palette::kPlan)},
                  {"first_plan", css(palette::kFirstPlan)},
                  {"charger", css(palette::kCharger)},
                  {"start", css(palette::kStart)},
                  {"moving", css(palette::kMoving)},
                  {"robot", css(palette::kRobot)},
                  {"axis", css(palette::kAxis)},
                  {"estimate", css(palette::kEstimate)},
                  {"stop", css(palette::kStopMark)},
                  {"replan", css(palette::kReplanMark)},
                  {"recovery", css(palette::kRecoveryMark)},
                  {"retry", css(palette::kRetryMark)},
                  {"collision", css(palette::kCollisionMark)},
                  {"failure", css(palette::kCollisionMark)},
                  {"sampled", css(palette::kSampledTrajectory)},
                  {"chosen", css(palette::kChosenTrajectory)}};
  return j;
}

// The player: plain JavaScript on a 2D canvas (anti-aliased by the browser).
constexpr const char* kPlayer = R"JS(
(function () {
  const D = JSON.parse(document.getElementById('replay-data').textContent);
  const canvas = document.getElementById('replay-canvas'), ctx = canvas.getContext('2d');
  const play = document.getElementById('replay-play'), speedSel = document.getElementById('replay-speed');
  const slider = document.getElementById('replay-slider'), zoomBox = document.getElementById('replay-zoom');
  const section = document.getElementById('replay');
  const C = D.colours, T = D.t, N = T.length, tEnd = N ? T[N - 1] : 0;
  const cividis = [[0,34,78],[53,69,108],[102,105,112],[148,142,119],[200,184,102],[254,232,56]];
  function speedColour(v) {
    let f = Math.min(1, Math.max(0, Math.abs(v) / D.max_speed)) * 5;
    const i = Math.min(4, Math.floor(f)); f -= i;
    const a = cividis[i], b = cividis[i + 1];
    return 'rgb(' + [0, 1, 2].map(k => Math.round(a[k] + f * (b[k] - a[k]))).join(',') + ')';
  }
  const dpr = window.devicePixelRatio || 1, W = canvas.width, H = canvas.height;
  canvas.width = W * dpr; canvas.height = H * dpr; canvas.style.width = W + 'px'; canvas.style.maxWidth = '100%';
  const legendW = 200, full = D.floor;
  let view = full.slice(), time = 0, playing = true, last = null, frames = 0;
  // A link may start the replay at a moment: report.html#t=53.4 (a failure's, say).
  const startAt = /[#&]t=([0-9]+(?:\.[0-9]+)?)/.exec(location.hash);
  if (startAt) time = Math.min(tEnd, parseFloat(startAt[1]));
  function index(t) { let lo = 0, hi = N - 1; while (lo < hi) { const m = (lo + hi + 1) >> 1; if (T[m] <= t) lo = m; else hi = m - 1; } return lo; }
  // The smallest box holding `pts`, `m` metres more on each side.
  function around(pts, m) {
    const xs = pts.map(p => p[0]), ys = pts.map(p => p[1]);
    return [Math.min(...xs) - m, Math.min(...ys) - m, Math.max(...xs) + m, Math.max(...ys) + m];
  }
  // Zoomed: on the dock while the robot docks near it, on the robot wherever else it docks (a
  // failed approach far from the charger), and from the failure on on its place together with
  // where the robot is and where it believes it is (an episode goes on after its failure's
  // moment: a kidnapped robot drives on, lost, for minutes).
  function targetView(i) {
    if (!zoomBox.checked || !N) return full;
    const F = D.failure;
    if (F && time >= F.t - 3) return around([[F.x, F.y], [D.x[i], D.y[i]], [D.ex[i], D.ey[i]]], 3);
    if (!D.docking[i]) return full;
    const near = Math.hypot(D.x[i] - D.dock[0], D.y[i] - D.dock[1]) < 1.5;
    const r = 1.5, cx = near ? D.dock[0] : D.x[i], cy = near ? D.dock[1] : D.y[i];
    return [cx - r, cy - r, cx + r, cy + r];
  }
  function transform() {
    const w = W - legendW - 20, h = H - 40, s = Math.min(w / (view[2] - view[0]), h / (view[3] - view[1]));
    const ox = 10 + (w - s * (view[2] - view[0])) / 2, oy = 30 + (h - s * (view[3] - view[1])) / 2;
    return { s: s, px: x => ox + s * (x - view[0]), py: y => oy + s * (view[3] - y) };
  }
  function rect(g, r, fill, stroke) {
    const x = g.px(r[0]), y = g.py(r[3]), w = g.s * (r[2] - r[0]), h = g.s * (r[3] - r[1]);
    if (fill) { ctx.fillStyle = fill; ctx.fillRect(x, y, w, h); }
    if (stroke) { ctx.strokeStyle = stroke; ctx.lineWidth = 2; ctx.strokeRect(x, y, w, h); }
  }
  function line(g, pts, colour, width, dash) {
    if (pts.length < 2) return;
    ctx.beginPath(); ctx.setLineDash(dash || []); ctx.strokeStyle = colour; ctx.lineWidth = width;
    pts.forEach((p, k) => k ? ctx.lineTo(g.px(p[0]), g.py(p[1])) : ctx.moveTo(g.px(p[0]), g.py(p[1])));
    ctx.stroke(); ctx.setLineDash([]);
  }
  // The controller's sketch in force at `t`: the last one made, while the robot travels and
  // at most 1.5 s old (sketches come about once a second).
  function sketchAt(t, i) {
    let best = null;
    for (const k of D.sketches) { if (k.t <= t) best = k; else break; }
    return best && t - best.t <= 1.5 && !D.docking[i] ? best : null;
  }
  function movingBox(m, t) {
    let k = 0; while (k + 1 < m.t.length && m.t[k + 1] <= t) k++;
    return m.boxes[k];
  }
  function draw() {
    ctx.setTransform(dpr, 0, 0, dpr, 0, 0);
    ctx.fillStyle = '#fff'; ctx.fillRect(0, 0, W, H);
    const i = index(time), g = transform();
    ctx.save(); ctx.beginPath(); ctx.rect(10, 30, W - legendW - 20, H - 40); ctx.clip();
    rect(g, full, C.floor, C.axis);
    D.obstacles.forEach(r => rect(g, r, C.obstacle));
    D.unmapped.forEach(r => rect(g, r, null, C.unmapped));
    // Before the last replan the first plan is the one being followed: drawn as the plan.
    const replanned = time >= D.plan_from_t;
    if (replanned) line(g, D.first_plan, C.first_plan, 1.5, [6, 5]);
    // A carry (a kidnap) is no driving: no trail across it, a thin dotted line from where the
    // robot was lifted to where it was set down.
    const carriedIn = k => D.carries.some(c => T[k - 1] <= c.t && c.t <= T[k]);  // a carry's own time is either side
    D.carries.forEach(c => {  // the carry dotted, the landing a triangle with the kidnap's time
      if (c.t > time) return;
      line(g, [c.from, c.to], C.axis, 1, [2, 4]);
      const x = g.px(c.to[0]), y = g.py(c.to[1]);
      ctx.fillStyle = C.axis; ctx.beginPath(); ctx.moveTo(x, y - 7); ctx.lineTo(x + 6, y + 5); ctx.lineTo(x - 6, y + 5); ctx.closePath(); ctx.fill();
      ctx.font = '12px DejaVu Sans, sans-serif'; ctx.fillText('kidnapped at ' + c.t.toFixed(1) + ' s', x + 9, y + 4);
    });
    for (let k = 1; k <= i; k++) {
      if (carriedIn(k)) continue;
      ctx.beginPath(); ctx.strokeStyle = speedColour(D.v[k]); ctx.lineWidth = 4; ctx.lineCap = 'round';
      ctx.moveTo(g.px(D.x[k - 1]), g.py(D.y[k - 1])); ctx.lineTo(g.px(D.x[k]), g.py(D.y[k])); ctx.stroke();
    }
    line(g, replanned || !D.first_plan.length ? D.plan : D.first_plan, C.plan, 1.5);
    const sk = sketchAt(time, i);  // what a sampling controller weighed at its last sketch
    if (sk) { sk.s.forEach(p => line(g, p, C.sampled, 1)); line(g, sk.c, C.chosen, 2.5); }
    D.moving.forEach(m => { if (m.t.length) rect(g, movingBox(m, time), C.moving, C.axis); });
    const cb = D.charger;
    ctx.save(); ctx.translate(g.px(cb[0]), g.py(cb[1])); ctx.rotate(-cb[4]);
    ctx.fillStyle = C.charger; ctx.fillRect(-g.s * cb[2], -g.s * cb[3], 2 * g.s * cb[2], 2 * g.s * cb[3]); ctx.restore();
    ctx.fillStyle = C.start; ctx.beginPath(); ctx.arc(g.px(D.start[0]), g.py(D.start[1]), 5, 0, 2 * Math.PI); ctx.fill();
    if (N) {  // what the robot believed: its estimated path so far and where it thinks it is
      const est = []; for (let k = 0; k <= i; k++) est.push([D.ex[k], D.ey[k]]);
      line(g, est, C.estimate, 2, [4, 3]);
      ctx.strokeStyle = C.estimate; ctx.lineWidth = 2; ctx.beginPath();
      ctx.arc(g.px(D.ex[i]), g.py(D.ey[i]), Math.max(6, g.s * D.robot.radius), 0, 2 * Math.PI); ctx.stroke();
    }
    D.events.forEach(e => {  // each event from its time on, a mark of its kind
      if (e.t > time) return;
      const x = g.px(e.x), y = g.py(e.y); ctx.strokeStyle = C[e.k] || C.axis; ctx.lineWidth = 2; ctx.beginPath();
      if (e.k === 'collision' || e.k === 'failure') { ctx.moveTo(x - 6, y - 6); ctx.lineTo(x + 6, y + 6); ctx.moveTo(x - 6, y + 6); ctx.lineTo(x + 6, y - 6); }
      else if (e.k === 'retry') ctx.rect(x - 5, y - 5, 10, 10);
      else ctx.arc(x, y, 6, 0, 2 * Math.PI);
      ctx.stroke();
    });
    if (N) {  // the robot: footprint and heading, never under 8 px across
      const x = g.px(D.x[i]), y = g.py(D.y[i]), a = D.yaw[i];
      const grow = Math.max(1, 4 / (g.s * D.robot.radius));
      ctx.save(); ctx.translate(x, y); ctx.rotate(-a); ctx.strokeStyle = C.robot; ctx.lineWidth = 2;
      ctx.beginPath();
      if (D.robot.length > 0) ctx.rect(-g.s * grow * D.robot.length / 2, -g.s * grow * D.robot.width / 2, g.s * grow * D.robot.length, g.s * grow * D.robot.width);
      else ctx.arc(0, 0, g.s * grow * D.robot.radius, 0, 2 * Math.PI);
      ctx.moveTo(0, 0); ctx.lineTo(g.s * grow * (D.robot.length > 0 ? D.robot.length / 2 : D.robot.radius), 0);
      ctx.stroke(); ctx.restore();
    }
    ctx.restore();
    // Clock and legend.
    ctx.fillStyle = C.axis; ctx.font = 'bold 15px DejaVu Sans, sans-serif';
    const off = N ? Math.hypot(D.x[i] - D.ex[i], D.y[i] - D.ey[i]) : 0;
    const clock = D.world + '   t = ' + time.toFixed(1) + ' s of ' + tEnd.toFixed(1) + ' s   ' +
                  (N && D.docking[i] ? 'docking' : 'travel') + '   ' + speedSel.value + 'x   estimate ' +
                  (1000 * off).toFixed(0) + ' mm off (sigma ' + (N ? (1000 * D.sigma[i]).toFixed(0) : 0) + ' mm)';
    ctx.fillText(clock, 10, 20);
    // The estimator's own verdict at this frame, in the failure's colour when it says lost.
    const health = N ? ['ok', 'degraded', 'lost'][D.health[i]] : 'ok';
    const clockWidth = ctx.measureText(clock).width;
    ctx.fillStyle = health === 'ok' ? C.axis : health === 'lost' ? C.failure : C.retry;
    ctx.fillText('   estimator ' + health, 10 + clockWidth, 20);
    section.dataset.replayEstimator = health;
    const F = D.failure;
    if (F && time >= Math.min(F.t, tEnd) - 1e-3) {  // the end: why
      ctx.font = 'bold 15px DejaVu Sans, sans-serif';
      ctx.fillStyle = 'rgba(255,255,255,0.9)'; ctx.fillRect(4, H - 32, W - 8, 28);  // over the map
      ctx.fillStyle = C.failure;
      ctx.fillText('FAILED: ' + F.reason + ' at t = ' + F.t.toFixed(1) + ' s, (' + F.x.toFixed(2) + ', ' +
                   F.y.toFixed(2) + ') m' + (F.detail ? ': ' + F.detail : ''), 10, H - 12, W - 20);
    }
    // Each entry's swatch is drawn as the map draws it (line, dashes, ring, cross, square, ...),
    // so that entries stay apart by shape where colours do not (colour-vision deficiencies).
    const items = [['plan', C.plan, 'line'], ['driven (speed)', speedColour(D.max_speed * 0.6), 'thick'],
                   ['robot', C.robot, 'ring'], ['estimate (dashed)', C.estimate, 'dash'],
                   ['charger', C.charger, 'fill'], ['start', C.start, 'dot']];
    const marks = { stop: 'ring', replan: 'ring', recovery: 'ring', retry: 'square', collision: 'cross' };
    ['stop', 'replan', 'recovery', 'retry', 'collision'].forEach(k => {
      if (D.events.some(e => e.k === k)) items.push([k, C[k], marks[k]]);
    });
    if (F) items.push(['failure (cross)', C.failure, 'cross']);
    if (D.obstacles.length) items.push(['obstacle', C.obstacle, 'fill']);
    if (D.first_plan.length && replanned) items.push(['first plan', C.first_plan, 'dash']);
    if (D.moving.length) items.push([D.moving_label, C.moving, 'fill']);
    if (D.unmapped.length) items.push(['not on map', C.unmapped, 'outline']);
    if (D.carries.length) items.push(['kidnap: carry, landing', C.axis, 'tri']);
    if (D.sketches.length) {
      items.push(['sampled trajectories', C.sampled, 'line']);
      items.push(['chosen trajectory', C.chosen, 'thick']);
    }
    ctx.font = '13px DejaVu Sans, sans-serif';
    items.forEach((it, k) => {
      const y = 50 + 20 * k, x = W - legendW, cy = y - 5;
      ctx.fillStyle = it[1]; ctx.strokeStyle = it[1]; ctx.lineWidth = 2; ctx.beginPath();
      switch (it[2]) {
        case 'thick': ctx.fillRect(x, cy - 3, 22, 6); break;
        case 'fill': ctx.fillRect(x + 4, cy - 6, 14, 12); break;
        case 'outline': ctx.strokeRect(x + 4, cy - 6, 14, 12); break;
        case 'square': ctx.strokeRect(x + 6, cy - 5, 10, 10); break;
        case 'ring': ctx.arc(x + 11, cy, 6, 0, 2 * Math.PI); ctx.stroke(); break;
        case 'dot': ctx.arc(x + 11, cy, 5, 0, 2 * Math.PI); ctx.fill(); break;
        case 'cross': ctx.moveTo(x + 5, cy - 6); ctx.lineTo(x + 17, cy + 6); ctx.moveTo(x + 5, cy + 6); ctx.lineTo(x + 17, cy - 6); ctx.stroke(); break;
        case 'tri': ctx.moveTo(x + 11, cy - 7); ctx.lineTo(x + 17, cy + 5); ctx.lineTo(x + 5, cy + 5); ctx.closePath(); ctx.fill(); break;
        case 'dash': ctx.setLineDash([4, 3]); ctx.moveTo(x, cy); ctx.lineTo(x + 22, cy); ctx.stroke(); ctx.setLineDash([]); break;
        default: ctx.lineWidth = 1.5; ctx.moveTo(x, cy); ctx.lineTo(x + 22, cy); ctx.stroke();
      }
      ctx.fillStyle = C.axis; ctx.fillText(it[0], W - legendW + 30, y);
    });
    section.dataset.replayLegend = items.map(it => it[0]).join('|');
    // Whether the robot and its estimate lie inside the view asked for (the browser test's
    // check of the framing; the canvas shows at least this much).
    const inside = (x, y) => x >= view[0] && x <= view[2] && y >= view[1] && y <= view[3];
    section.dataset.replayInView = N ? [inside(D.x[i], D.y[i]) ? 'robot' : '',
                                        inside(D.ex[i], D.ey[i]) ? 'estimate' : ''].filter(Boolean).join(' ') : '';
    frames++;
    section.dataset.replayFrames = frames; section.dataset.replayTime = time.toFixed(3);
    slider.value = tEnd > 0 ? Math.round(1000 * time / tEnd) : 0;
  }
  // Frames at 30 per second by timer (a hidden tab slows it; a headless test's virtual clock
  // runs it), each advancing the replay by the real time elapsed times the chosen speed.
  function tick() {
    const now = performance.now();
    if (last !== null && playing) {
      time += (now - last) / 1000 * parseFloat(speedSel.value);
      if (time >= tEnd) { time = tEnd; playing = false; play.textContent = 'play'; }
    }
    last = now;
    const goal = targetView(index(time)), f = 0.08;  // ease into and out of the docking close-up
    view = view.map((v, k) => v + f * (goal[k] - v));
    draw();
    setTimeout(tick, 1000 / 30);
  }
  play.onclick = () => { if (time >= tEnd) time = 0; playing = !playing; play.textContent = playing ? 'pause' : 'play'; };
  slider.oninput = () => { time = tEnd * slider.value / 1000; };
  tick();
})();
)JS";

}  // namespace

std::string replay_html(const worlds::World& world, const episode::EpisodeResult& run,
                        const ReplayOptions& o) {
  // Inside a script element "</script" ends it early and "<!--" opens the HTML parser's escaped
  // states (a world named "<!--<script>" hid the player): JSON holds "<", ">" and "&" only inside
  // strings, where "\u003c" and the like read back the same.
  std::string data;
  for (const char c : replay_data(world, run, o).dump())
    data += c == '<'   ? std::string("\\u003c")
            : c == '>' ? std::string("\\u003e")
            : c == '&' ? std::string("\\u0026")
                       : std::string(1, c);
  std::string h = "<section id=\"replay\" data-replay-frames=\"0\">\n<h2>Replay</h2>\n";
  h += "<canvas id=\"replay-canvas\" width=\"" + std::to_string(o.width_px) + "\" height=\"" +
       std::to_string(o.height_px) + "\"></canvas>\n";
  h += "<p><button id=\"replay-play\">pause</button> speed <select "
       "id=\"replay-speed\"><option>0.5</option>"
       "<option>1</option><option>2</option><option "
       "selected>4</option><option>8</option><option>16</option></select> "
       "<input id=\"replay-slider\" type=\"range\" min=\"0\" max=\"1000\" value=\"0\" "
       "style=\"width:50%\"> "
       "<label><input id=\"replay-zoom\" type=\"checkbox\" checked> zoom on the "
       "docking and the failure</label></p>\n";
  h += "<script type=\"application/json\" id=\"replay-data\">" + data + "</script>\n";
  h += std::string("<script>") + kPlayer + "</script>\n</section>\n";
  return h;
}

}  // namespace plantsim::render
