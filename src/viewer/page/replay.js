// graspsim replay viewer: plays back GRASPSIM_REPLAY (built by src/viewer/replay_page.cpp) with
// three.js. Poses are precomputed per sample, so this script only places meshes.
(function () {
  "use strict";
  var data = GRASPSIM_REPLAY;
  var nFrames = data.times.length;
  var nBodies = data.bodies.length;
  var FINGERS = ["thumb", "index", "middle", "ring", "little"];
  var FINGER_COLOURS = { thumb: "#8e44ad", index: "#2980b9", middle: "#16a085", ring: "#d35400", little: "#c0392b" };
  var AXES = ["rx", "ry", "rz", "x", "y", "z"];

  function $(id) { return document.getElementById(id); }
  function isEngagedAt(t) {
    for (var i = 0; i < data.engaged.length; i++) if (t >= data.engaged[i][0] - 1e-12 && t <= data.engaged[i][1] + 1e-12) return true;
    return false;
  }
  function pose(frame, body) { var p = data.poses[frame], k = 7 * body; return p.slice(k, k + 7); }

  // --- scene ---------------------------------------------------------------------------------
  var view = $("view");
  var renderer = new THREE.WebGLRenderer({ antialias: true, preserveDrawingBuffer: true });
  renderer.setPixelRatio(window.devicePixelRatio || 1);
  renderer.setClearColor(0xf4f4f2);
  view.appendChild(renderer.domElement);
  var scene = new THREE.Scene();
  scene.background = new THREE.Color(0xf4f4f2);
  scene.add(new THREE.HemisphereLight(0xffffff, 0x888877, 0.75));
  var sun = new THREE.DirectionalLight(0xffffff, 0.6);
  sun.position.set(1, 2, 1.5);
  scene.add(sun);
  var camera = new THREE.PerspectiveCamera(35, 1, 0.01, 20);

  var skin = new THREE.MeshLambertMaterial({ color: 0xe0b49a });
  var armSkin = new THREE.MeshLambertMaterial({ color: 0xd6a98f });
  var objectMaterial = new THREE.MeshLambertMaterial({ color: data.bodies[nBodies - 1].geoms[0].type === "box" ? 0x34495e : 0xf39c12 });

  function makeShape(g, material) {
    var mesh;
    if (g.type === "sphere") {
      mesh = new THREE.Mesh(new THREE.SphereBufferGeometry(g.r, 32, 20), material);
    } else if (g.type === "box") {
      mesh = new THREE.Mesh(new THREE.BoxBufferGeometry(2 * g.half[0], 2 * g.half[1], 2 * g.half[2]), material);
    } else if (g.type === "capsule" || g.type === "cylinder") {
      // graspsim's axis is the geometry frame's z; three.js builds cylinders along y.
      mesh = new THREE.Group();
      var body = new THREE.Mesh(new THREE.CylinderBufferGeometry(g.r, g.r, g.len, 24), material);
      body.rotation.x = Math.PI / 2;
      mesh.add(body);
      if (g.type === "capsule") {
        [-1, 1].forEach(function (s) {
          var cap = new THREE.Mesh(new THREE.SphereBufferGeometry(g.r, 24, 12), material);
          cap.position.z = s * g.len / 2;
          mesh.add(cap);
        });
      }
    } else if (g.type === "ellipsoid") {
      // A unit sphere scaled by the semi-axes.
      mesh = new THREE.Mesh(new THREE.SphereBufferGeometry(1, 32, 20), material);
      mesh.scale.set(g.semi[0], g.semi[1], g.semi[2]);
    } else if (g.type === "mesh" && g.verts) {
      var geometry = new THREE.BufferGeometry();
      geometry.setAttribute("position", new THREE.Float32BufferAttribute(g.verts, 3));
      geometry.setIndex(g.tris);
      // One normal per face (the mesh is a convex polyhedron of flat faces), not smoothed over corners.
      geometry = geometry.toNonIndexed();
      geometry.computeVertexNormals();
      mesh = new THREE.Mesh(geometry, material);
    } else {
      return null;  // a mesh known only by file name (an imported URDF's display mesh)
    }
    mesh.position.set(g.pose[0], g.pose[1], g.pose[2]);
    mesh.quaternion.set(g.pose[4], g.pose[5], g.pose[6], g.pose[3]);
    return mesh;
  }

  var groups = [], drawn = 0;
  data.bodies.forEach(function (b, i) {
    var group = new THREE.Group();
    var material = b.finger === "object" ? objectMaterial : (b.finger ? skin : armSkin);
    b.geoms.forEach(function (g) { var m = makeShape(g, material); if (m) group.add(m); });
    if (group.children.length > 0) drawn++;
    scene.add(group);
    groups.push(group);
  });

  // The object's path over the whole run.
  var objectIndex = nBodies - 1;
  var pathPoints = [];
  for (var f = 0; f < nFrames; f++) { var op = pose(f, objectIndex); pathPoints.push(new THREE.Vector3(op[0], op[1], op[2])); }
  var pathLine = new THREE.Line(new THREE.BufferGeometry().setFromPoints(pathPoints), new THREE.LineBasicMaterial({ color: 0x7d3c98 }));
  scene.add(pathLine);
  var marker = new THREE.Mesh(new THREE.SphereBufferGeometry(0.0025, 12, 8), new THREE.MeshBasicMaterial({ color: 0x7d3c98 }));
  scene.add(marker);

  // Force arrows: one scale for the whole run, a round number of newtons per centimetre that draws
  // the 95th percentile of the forces about 5 cm long (the largest, at impacts, would shrink the rest).
  var magnitudes = [];
  data.contacts.forEach(function (cs) { cs.forEach(function (c) { magnitudes.push(Math.hypot(c[3], c[4], c[5])); }); });
  data.constraintSamples.forEach(function (s) { if (s) magnitudes.push(Math.hypot(s.reaction[3], s.reaction[4], s.reaction[5])); });
  magnitudes.sort(function (a, b) { return a - b; });
  var typicalForce = magnitudes.length ? magnitudes[Math.floor(0.95 * (magnitudes.length - 1))] : 0;
  function niceNumber(x) { var e = Math.pow(10, Math.floor(Math.log10(x))), m = x / e; return (m < 1.5 ? 1 : m < 3.5 ? 2 : m < 7.5 ? 5 : 10) * e; }
  var newtonsPerCm = typicalForce > 0 ? niceNumber(typicalForce / 5) : 1;
  var metresPerNewton = 0.01 / newtonsPerCm;
  // Arrows and the constraint's axes are drawn over the bodies: a force acts where fingers and
  // object meet, inside what would hide it.
  function drawOnTop(object) {
    object.renderOrder = 10;
    object.traverse(function (o) { if (o.material) { o.material.depthTest = false; o.material.transparent = true; } });
    return object;
  }
  // A solid arrow along +y from its origin: shaft, head and a dot at its tip (the point of action).
  var HEAD = 0.007;
  function makeArrow(colour) {
    var material = new THREE.MeshBasicMaterial({ color: colour });
    var shaftGeometry = new THREE.CylinderBufferGeometry(0.0011, 0.0011, 1, 8);
    shaftGeometry.translate(0, 0.5, 0);
    var a = new THREE.Group();
    a.add(new THREE.Mesh(shaftGeometry, material));
    a.add(new THREE.Mesh(new THREE.ConeBufferGeometry(0.003, HEAD, 12), material));
    a.add(new THREE.Mesh(new THREE.SphereBufferGeometry(0.0018, 10, 6), material));
    scene.add(drawOnTop(a));
    return a;
  }
  var arrows = [];
  function getArrow(i) {
    while (arrows.length <= i) arrows.push(makeArrow(0xc0392b));
    return arrows[i];
  }
  // The arrow ends at the point p, where force f (N) acts: it pushes the object from outside.
  var Y = new THREE.Vector3(0, 1, 0);
  function placeArrow(a, p, f) {
    var n = Math.hypot(f[0], f[1], f[2]);
    var len = n * metresPerNewton;
    a.visible = true;
    a.children[0].visible = a.children[1].visible = len > 1e-4;
    var u = n > 1e-12 ? new THREE.Vector3(f[0] / n, f[1] / n, f[2] / n) : Y.clone();
    a.position.set(p[0] - u.x * len, p[1] - u.y * len, p[2] - u.z * len);
    a.quaternion.setFromUnitVectors(Y, u);
    var head = Math.min(HEAD, 0.5 * len);
    a.children[0].scale.set(1, Math.max(len - head, 1e-6), 1);
    a.children[1].scale.set(head / HEAD, head / HEAD, head / HEAD);
    a.children[1].position.set(0, len - head / 2, 0);
    a.children[2].position.set(0, len, 0);
  }
  var reactionArrow = makeArrow(0x27ae60);
  var constraintAxes = drawOnTop(new THREE.AxesHelper(0.025));
  scene.add(constraintAxes);

  // --- panels ----------------------------------------------------------------------------------
  var perturbation = data.perturbation === "none" ? "no perturbation" : "perturbation " + data.perturbation;
  var ramp = data.provenance.run && data.provenance.run.ramp ? ", ramp " + data.provenance.run.ramp : "";  // simulate --ramp
  $("title").textContent = data.scenario + ": " + data.mode + (data.mode === "approx" ? " (" + data.constraint + ")" : "") + ", " + data.contact + " contact, " + perturbation + ramp;
  $("subtitle").textContent = "graspsim " + data.provenance.graspsim.version + " (" + String(data.provenance.graspsim.commit).slice(0, 10) + ")" +
    (data.failure ? " \u2014 INCOMPLETE RUN, stopped at " + data.simTime + " s: " + data.failure : "");
  $("legend").innerHTML =
    '<svg width="40" height="10"><line x1="2" y1="5" x2="30" y2="5" stroke="#c0392b" stroke-width="2"/><polygon points="30,1 38,5 30,9" fill="#c0392b"/></svg> contact force on the object' +
    (data.mode === "approx" ? '<br><svg width="40" height="10"><line x1="2" y1="5" x2="30" y2="5" stroke="#27ae60" stroke-width="2"/><polygon points="30,1 38,5 30,9" fill="#27ae60"/></svg> constraint reaction on the object' : "") +
    "<br>arrow scale: 1 cm = " + newtonsPerCm + " N" +
    '<br><svg width="40" height="10"><line x1="2" y1="5" x2="38" y2="5" stroke="#7d3c98" stroke-width="2"/></svg> path of the object';
  var fingerRows = {};
  FINGERS.forEach(function (name) {
    var tr = document.createElement("tr");
    tr.innerHTML = '<td><span class="dot" style="background:' + FINGER_COLOURS[name] + '"></span>' + name + "</td><td></td>";
    $("fingertable").appendChild(tr);
    fingerRows[name] = tr.children[1];
  });
  var constraintRows = AXES.map(function (axis) {
    var tr = document.createElement("tr");
    tr.innerHTML = "<td>" + axis + '</td><td><span class="bar"><span></span></span></td><td></td>';
    $("constrainttable").appendChild(tr);
    return tr;
  });
  var end = data.times[nFrames - 1];
  data.engaged.forEach(function (iv) {
    var d = document.createElement("div");
    d.style.left = (100 * iv[0] / end) + "%";
    d.style.width = Math.max(0.3, 100 * (iv[1] - iv[0]) / end) + "%";
    d.title = "approximation engaged " + iv[0].toFixed(3) + "-" + iv[1].toFixed(3) + " s";
    $("engaged").appendChild(d);
  });
  $("barlegend").innerHTML = data.mode === "approx"
    ? '<span class="swatch"></span>approximation engaged (' + data.engaged.length + " interval" + (data.engaged.length === 1 ? "" : "s") + ")"
    : "full contact throughout (no approximation in this run)";
  var scrub = $("scrub");
  scrub.max = String(nFrames - 1);

  // --- one frame -------------------------------------------------------------------------------
  var current = 0;
  function showFrame(frame) {
    current = frame;
    var t = data.times[frame];
    for (var b = 0; b < nBodies; b++) {
      var p = pose(frame, b);
      groups[b].position.set(p[0], p[1], p[2]);
      groups[b].quaternion.set(p[4], p[5], p[6], p[3]);
    }
    marker.position.set(pathPoints[frame].x, pathPoints[frame].y, pathPoints[frame].z);
    var contacts = data.contacts[frame], perFinger = {};
    arrows.forEach(function (a) { a.visible = false; });
    contacts.forEach(function (c, i) {
      placeArrow(getArrow(i), c, [c[3], c[4], c[5]]);
      var f = c[6] || "palm";
      perFinger[f] = (perFinger[f] || 0) + Math.hypot(c[3], c[4], c[5]);
    });
    var engaged = isEngagedAt(t), sample = data.constraintSamples[frame];
    FINGERS.forEach(function (name) {
      // Merged: the fingers are locked to the palm; multi: each attached finger is part of the
      // approximation's element (no single constraint to show).
      fingerRows[name].textContent = engaged && sample ? "locked to the palm"
        : engaged ? "held by the approximation"
        : perFinger[name] ? "contact, " + perFinger[name].toFixed(2) + " N" : "free";
    });
    reactionArrow.visible = constraintAxes.visible = !!sample;
    $("constraint").style.display = sample ? "block" : "none";
    if (sample) {
      var q = new THREE.Quaternion(sample.pose[4], sample.pose[5], sample.pose[6], sample.pose[3]);
      constraintAxes.position.set(sample.pose[0], sample.pose[1], sample.pose[2]);
      constraintAxes.quaternion.copy(q);
      var force = new THREE.Vector3(sample.reaction[3], sample.reaction[4], sample.reaction[5]).applyQuaternion(q);
      placeArrow(reactionArrow, sample.pose, [force.x, force.y, force.z]);
      constraintRows.forEach(function (tr, k) {
        var limit = sample.limits[k], r = Math.abs(sample.reaction[k]), unit = k < 3 ? " N m" : " N";
        var fraction = limit === null ? 0 : limit > 0 ? Math.min(1, r / limit) : 1;
        tr.children[1].firstChild.className = "bar" + (fraction >= 0.999 ? " over" : "");
        tr.children[1].firstChild.firstChild.style.width = (100 * fraction) + "%";
        tr.children[2].textContent = r.toFixed(3) + " / " + (limit === null ? "locked" : limit.toFixed(3)) + unit;
      });
    }
    $("time").textContent = t.toFixed(3);
    $("quality").textContent = data.quality[frame].toFixed(3);
    $("phase").textContent = engaged ? "approximation engaged" : (data.mode === "approx" ? "full contact (approximation not engaged)" : "full contact");
    scrub.value = String(frame);
    renderer.render(scene, camera);
  }

  function findFrame(t) {
    var lo = 0, hi = nFrames - 1;
    while (lo < hi) { var mid = (lo + hi + 1) >> 1; if (data.times[mid] <= t + 1e-9) lo = mid; else hi = mid - 1; }
    return lo;
  }

  // --- camera, size, controls --------------------------------------------------------------------
  var o0 = pathPoints[0];
  // Looking at the hand from the subject's right, a little in front and above: the fingers press
  // along the view's plane, so their force arrows show their length.
  var target = new THREE.Vector3(0.8 * o0.x, 0.8 * o0.y, 0.8 * o0.z);
  camera.position.set(target.x + 0.24, target.y + 0.1, target.z + 0.5);
  var controls = new THREE.OrbitControls(camera, renderer.domElement);
  controls.target.copy(target);
  controls.update();
  controls.addEventListener("change", function () { renderer.render(scene, camera); });
  function resize() {
    var w = view.clientWidth || window.innerWidth, h = view.clientHeight || window.innerHeight;
    renderer.setSize(w, h);
    camera.aspect = w / h;
    camera.updateProjectionMatrix();
    renderer.render(scene, camera);
  }
  window.addEventListener("resize", resize);

  var playing = false, speed = 1, simTime = 0, lastWall = 0;
  function tick(now) {
    if (!playing) return;
    simTime += (now - lastWall) / 1000 * speed;
    lastWall = now;
    if (simTime >= end) { simTime = end; playing = false; $("play").textContent = "Play"; }
    showFrame(findFrame(simTime));
    if (playing) requestAnimationFrame(tick);
  }
  $("play").addEventListener("click", function () {
    playing = !playing;
    $("play").textContent = playing ? "Pause" : "Play";
    if (playing) {
      if (current >= nFrames - 1) simTime = 0;
      lastWall = performance.now();
      requestAnimationFrame(tick);
    }
  });
  $("speed").addEventListener("change", function () { speed = parseFloat(this.value); });
  scrub.addEventListener("input", function () { simTime = data.times[parseInt(this.value, 10)]; showFrame(parseInt(this.value, 10)); });

  // replay.html?t=SECONDS: that instant, still (for pictures).
  var match = /[?&]t=([-+0-9.eE]+)/.exec(window.location.search);
  var startFrame = match ? findFrame(parseFloat(match[1])) : 0;
  simTime = data.times[startFrame];
  resize();
  showFrame(startFrame);

  var gl = renderer.getContext();
  var state = { frames: nFrames, bodies: nBodies, drawn: drawn, time: data.times[startFrame], webgl: !!gl, errors: window.graspsimErrors };
  $("replay-state").textContent = JSON.stringify(state);
  document.title = "graspsim replay: ready";
})();
