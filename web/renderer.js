// WebGL2 side of the page: compiles the shaders the core assembled (GLSL ES 3.00 from the
// same templates as the desktop), holds the hierarchy texture, sets the uniforms the core
// computed for a frame and draws it, in tiles when a frame is slow, so that no single
// draw runs long enough to trip the browser's GPU watchdog. Recovers a lost context. Links
// programs in the background where the browser can (KHR_parallel_shader_compile), so the
// page keeps drawing a formula's first picture (the tape interpreter's, with its tape and
// hierarchy in textures of their own) while the formula's own shader compiles. No scene
// logic here: every number comes from the core (src/web/web_session.hpp).

const NODE_ROW = 1024;  // texels per row of the hierarchy and tape textures (the templates' rows)
const TILE_BUDGET_MS = 40;  // a frame slower than this is drawn in tiles over several tasks

export class Renderer {
  static LOST = 'lost';  // use()'s answer while the context is lost: not an error

  constructor(canvas, { onRestored } = {}) {
    this.canvas = canvas;
    this.onRestored = onRestored;
    this.programs = new Map();  // vertex + fragment text -> { program, locations }
    this.lost = false;
    this.hierarchy = null;      // the last texels uploaded, to upload again after a loss
    this.textures = {};         // 'own' and 'quick' hierarchies, 'tape': texture objects
    this.hierarchyGeneration = -1;
    this.lastFrameMs = 0;
    this.drawId = 0;
    canvas.addEventListener('webglcontextlost', (e) => {
      e.preventDefault();  // ask for the context back
      this.lost = true;
      this.drawId++;
    });
    canvas.addEventListener('webglcontextrestored', () => {
      this.lost = false;
      this.init();
      if (this.hierarchy) this.uploadHierarchy(this.hierarchy.texels, this.hierarchy.count);
      if (this.onRestored) this.onRestored();
    });
    this.init();
  }

  init() {
    const gl = this.canvas.getContext('webgl2', {
      antialias: false, depth: false, stencil: false, alpha: false,
      preserveDrawingBuffer: true,  // tiles accumulate; PNG download reads the canvas
      powerPreference: 'high-performance',
    });
    if (!gl) throw new Error('this browser has no WebGL2');
    this.gl = gl;
    this.programs.clear();
    this.vao = gl.createVertexArray();
    this.textures = {};
    this.hierarchyGeneration = -1;
    this.parallel = gl.getExtension('KHR_parallel_shader_compile');
  }

  // Starts linking the program for these sources, or finds it; returns its entry, or
  // Renderer.LOST. The link may still run (ready() says when it is done); finish() waits.
  request(vertex, fragment) {
    if (this.gl.isContextLost()) return Renderer.LOST;  // restored later: onRestored draws
    const key = vertex + '\u0000' + fragment;
    let entry = this.programs.get(key);
    if (entry) {  // most recently used last: the oldest is dropped first
      this.programs.delete(key);
      this.programs.set(key, entry);
      return entry;
    }
    const gl = this.gl;
    const compile = (type, source) => {
      const s = gl.createShader(type);
      gl.shaderSource(s, source);
      gl.compileShader(s);
      return s;
    };
    const vs = compile(gl.VERTEX_SHADER, vertex);
    const fs = compile(gl.FRAGMENT_SHADER, fragment);
    const program = gl.createProgram();
    gl.attachShader(program, vs);
    gl.attachShader(program, fs);
    gl.linkProgram(program);
    // Keep a few: parameter edits and view changes reuse the program; a new formula or a
    // new lighting variant makes another; the interpreters' stay in use while typing.
    if (this.programs.size >= 8) {
      const [oldKey, old] = this.programs.entries().next().value;
      gl.deleteProgram(old.program);
      this.programs.delete(oldKey);
    }
    entry = { program, vs, fs, locations: new Map(), log: null };
    this.programs.set(key, entry);
    return entry;
  }

  // Whether the entry's link has finished (always, without the extension).
  ready(entry) {
    if (entry === Renderer.LOST || entry.log !== null || !this.parallel) return true;
    return this.gl.getProgramParameter(entry.program, this.parallel.COMPLETION_STATUS_KHR);
  }

  // Waits for the link and makes the program current; '' or the driver's log.
  finish(entry) {
    if (entry === Renderer.LOST) return Renderer.LOST;
    const gl = this.gl;
    if (entry.log === null) {
      entry.log = '';
      if (!gl.getProgramParameter(entry.program, gl.LINK_STATUS)) {
        if (gl.isContextLost()) return 'the WebGL context was lost';
        entry.log = (gl.getShaderInfoLog(entry.vs) || '') + (gl.getShaderInfoLog(entry.fs) || '') +
                    (gl.getProgramInfoLog(entry.program) || '') || 'the shader did not link';
      }
      gl.deleteShader(entry.vs);
      gl.deleteShader(entry.fs);
    }
    if (entry.log) return entry.log;
    this.current = entry;
    return '';
  }

  // Compiles (or reuses) the program for these sources, waiting for it; '' or the log.
  use(vertex, fragment) {
    return this.finish(this.request(vertex, fragment));
  }

  // The formula's own hierarchy ('own', kept to upload again after a context loss), the
  // first picture's ('quick') or the interpreter's tape ('tape'): texels in rows.
  uploadHierarchy(texels, count, which = 'own') {
    if (which === 'own') this.hierarchy = { texels, count };
    this.uploadRows(which, texels, count);
  }

  uploadTape(texels) {
    this.uploadRows('tape', texels, texels.length / 4);
  }

  uploadRows(which, texels, count) {
    const gl = this.gl;
    const rows = Math.max(1, Math.ceil(count / NODE_ROW));
    const data = new Uint32Array(NODE_ROW * rows * 4);
    data.set(texels.subarray(0, Math.min(texels.length, data.length)));
    if (!this.textures[which]) this.textures[which] = gl.createTexture();
    gl.bindTexture(gl.TEXTURE_2D, this.textures[which]);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MIN_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_MAG_FILTER, gl.NEAREST);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_S, gl.CLAMP_TO_EDGE);
    gl.texParameteri(gl.TEXTURE_2D, gl.TEXTURE_WRAP_T, gl.CLAMP_TO_EDGE);
    gl.pixelStorei(gl.UNPACK_ALIGNMENT, 4);
    gl.texImage2D(gl.TEXTURE_2D, 0, gl.RGBA32UI, NODE_ROW, rows, 0, gl.RGBA_INTEGER,
                  gl.UNSIGNED_INT, data);
  }

  setUniforms(uniforms) {
    const gl = this.gl;
    const { program, locations } = this.current;
    for (const u of uniforms) {
      let loc = locations.get(u.name);
      if (loc === undefined) {
        const name = u.kind === 'floats' ? u.name + '[0]' : u.name;
        loc = gl.getUniformLocation(program, name);
        locations.set(u.name, loc);
      }
      if (loc === null) continue;  // not read by this program: the compiler removed it
      switch (u.kind) {
        case 'int': gl.uniform1i(loc, u.value); break;
        case 'float': gl.uniform1f(loc, u.value[0]); break;
        case 'vec2': gl.uniform2fv(loc, u.value); break;
        case 'vec3': gl.uniform3fv(loc, u.value); break;
        case 'vec4': gl.uniform4fv(loc, u.value); break;
        case 'mat4': gl.uniformMatrix4fv(loc, false, u.value); break;
        case 'floats': gl.uniform1fv(loc, u.value); break;
      }
    }
  }

  bindTextures(quick) {
    const gl = this.gl;
    if (quick) {
      gl.activeTexture(gl.TEXTURE2);  // zs_tape (render/frame_uniforms.cpp)
      gl.bindTexture(gl.TEXTURE_2D, this.textures.tape || null);
    }
    gl.activeTexture(gl.TEXTURE0);
    gl.bindTexture(gl.TEXTURE_2D, this.textures[quick ? 'quick' : 'own'] || null);
  }

  // Draws a frame: `frameAt(w, h)` gives the core's uniforms for the drawing-buffer size.
  // Resolves with the milliseconds it took, or null when a newer draw or a lost context
  // superseded it. Slow frames go in horizontal bands, one band per task; `whole` draws one
  // band (frame-time measurements); `quick` draws with the first picture's textures.
  async draw(frameAt, background, { whole = false, quick = false } = {}) {
    const id = ++this.drawId;
    if (this.lost) return null;
    const gl = this.gl;
    const w = this.canvas.width, h = this.canvas.height;
    const frame = frameAt(w, h);
    const start = performance.now();
    const program = this.current;
    gl.useProgram(program.program);
    this.setUniforms(frame.uniforms);
    this.bindTextures(quick);
    gl.bindVertexArray(this.vao);
    gl.disable(gl.DEPTH_TEST);
    gl.disable(gl.BLEND);
    // The box proxy keeps its back faces: one fragment per pixel (render/frame_uniforms.hpp).
    gl.enable(gl.CULL_FACE);
    gl.cullFace(gl.FRONT);
    gl.frontFace(gl.CCW);
    gl.viewport(0, 0, w, h);
    gl.disable(gl.SCISSOR_TEST);
    gl.clearColor(background[0], background[1], background[2], 1);
    gl.clear(gl.COLOR_BUFFER_BIT);
    if (frame.vertices === 0) {
      gl.finish();
      return performance.now() - start;
    }
    // Bands: as many as the last frame's time asks for, so each stays within the budget.
    const bands = whole ? 1 : Math.min(64, Math.max(1, Math.ceil(this.lastFrameMs / TILE_BUDGET_MS)));
    const bandHeight = Math.ceil(h / bands);
    gl.enable(gl.SCISSOR_TEST);
    for (let b = 0; b < bands; b++) {
      if (id !== this.drawId || this.lost) {
        gl.disable(gl.SCISSOR_TEST);
        return null;
      }
      gl.useProgram(program.program);
      gl.bindVertexArray(this.vao);
      this.bindTextures(quick);
      gl.scissor(0, b * bandHeight, w, bandHeight);
      gl.drawArrays(gl.TRIANGLES, 0, frame.vertices);
      // A pixel read waits for the band (finish() need not), so the next band starts only
      // after this one and the time measured is the GPU's.
      const pixel = new Uint8Array(4);
      gl.readPixels(0, Math.min(b * bandHeight, h - 1), 1, 1, gl.RGBA, gl.UNSIGNED_BYTE, pixel);
      if (bands > 1 && b + 1 < bands) await new Promise((r) => setTimeout(r, 0));
    }
    gl.disable(gl.SCISSOR_TEST);
    const ms = performance.now() - start;
    if (!whole) this.lastFrameMs = ms;
    return ms;
  }
}
