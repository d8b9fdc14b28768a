//! The WebGL2 renderer: owns its context's programs and buffers, draws a [`DrawList`] with the
//! orbit camera, and returns where the labels go on screen. Per frame it only sets uniforms and
//! issues draw calls; the unit meshes and the toolpath are uploaded once per context.

use glam::{DAffine3, Mat3, Mat4};
use wasm_bindgen::{JsCast, JsValue};
use web_sys::{HtmlCanvasElement, WebGl2RenderingContext as Gl, WebGlUniformLocation};

use super::camera::{Camera, project_to_css};
use super::draw_list::{DrawList, Pass, Shape};
use super::gpu::{GpuLines, GpuMesh, GpuTriangles, Program, RenderError};
use super::machine_parts::BLANK;
use super::mesh::{self, Lines};
use super::stock::{self, CUT};
use super::toolpath::{self, PathPoint};
use super::triads;
use schwenkbar_app::scene::Scene;
use schwenkbar_app::stock::FRAME_RAYS;
use schwenkbar_core::stock::StockMesh;
use std::rc::Rc;

/// Background of the view (the control's dark graphics area).
pub const BACKGROUND: [f32; 3] = [0.11, 0.15, 0.20];

/// A label placed on screen (CSS pixels from the canvas' top left).
#[derive(Debug, Clone, PartialEq)]
pub struct ScreenLabel {
    pub text: &'static str,
    pub kind: &'static str,
    pub x: f32,
    pub y: f32,
}

struct LitUniforms {
    model_view: Option<WebGlUniformLocation>,
    projection: Option<WebGlUniformLocation>,
    colour: Option<WebGlUniformLocation>,
    /// The section plane in view space, `(n, d)`: a fragment with n·p + d > 0 is not drawn
    /// (zero, the default, draws everything).
    clip: Option<WebGlUniformLocation>,
    /// The colour of a triangle's back (alpha > 0; zero, the default: its front colour). The
    /// stock's inside is material: its back faces, seen through the gaps between the steps of
    /// two dexel grids on a tilted face or past the section plane, are drawn as cut material,
    /// not as the raw blank's faces behind (which showed as an orange lattice over a face milled
    /// at SPB+15).
    inside: Option<WebGlUniformLocation>,
}

/// Everything that lives in one GL context (rebuilt after a context loss).
///
/// The shaders (`shaders/*.vert|frag`) carry no comments because their text ships in the bundle:
/// `lit` lights meshes in view space, so every view of the machine is lit from the front (a key
/// light from the upper left behind the viewer, a weaker fill from the right, a floor of ambient
/// light so no face goes black on a projector, a small highlight); the normal matrix (inverse
/// transpose of the model-view, for non-uniformly scaled parts) is computed per vertex there.
/// `line` draws the toolpath in its vertex colours.
struct Gpu {
    lit: Program,
    lit_u: LitUniforms,
    line: Program,
    line_mvp: Option<WebGlUniformLocation>,
    shapes: Vec<GpuMesh>,
    toolpath: Option<GpuLines>,
    /// The stock uploaded, tile by tile ([`schwenkbar_core::stock::TiledMesh`]).
    stock: Vec<StockTile>,
}

/// One tile of the stock on the GPU: the mesh it was made from (a new `Rc` = a changed tile),
/// its triangles, how many vertices are the raw blank's (drawn first) and the total.
struct StockTile {
    mesh: Rc<StockMesh>,
    tris: GpuTriangles,
    raw: usize,
    all: usize,
}

impl Gpu {
    fn new(gl: &Gl, path: &Lines) -> Result<Gpu, RenderError> {
        let lit = Program::new(gl, include_str!("shaders/lit.vert"), include_str!("shaders/lit.frag"))?;
        let lit_u = LitUniforms {
            model_view: lit.uniform("u_model_view"),
            projection: lit.uniform("u_projection"),
            colour: lit.uniform("u_colour"),
            clip: lit.uniform("u_clip"),
            inside: lit.uniform("u_inside"),
        };
        let line = Program::new(gl, include_str!("shaders/line.vert"), include_str!("shaders/line.frag"))?;
        let line_mvp = line.uniform("u_mvp");
        let mut shapes = Vec::with_capacity(Shape::ALL.len());
        for s in Shape::ALL {
            shapes.push(GpuMesh::upload(gl, &unit_mesh(s))?);
        }
        let toolpath = if path.vertices.is_empty() { None } else { Some(GpuLines::upload(gl, path)?) };
        Ok(Gpu { lit, lit_u, line, line_mvp, shapes, toolpath, stock: Vec::new() })
    }
}

/// The unit mesh of each shape (`Shape::ALL` order).
fn unit_mesh(s: Shape) -> mesh::Mesh {
    match s {
        Shape::Cube => mesh::cuboid(glam::Vec3::splat(-0.5), glam::Vec3::splat(0.5)),
        Shape::Cylinder => mesh::cylinder(1.0, 1.0, 32),
        Shape::Cone => mesh::cone(1.0, 1.0, 24),
        Shape::CurlArc => mesh::torus_arc(1.0, Shape::CURL_TUBE, Shape::CURL_SWEEP, 48, 10),
        Shape::Square => mesh::square(1.0),
        Shape::Finger => mesh::torus_arc(1.0, Shape::FINGER_TUBE, Shape::CURL_SWEEP, 24, 10),
    }
}

/// The renderer of one canvas.
pub struct Renderer {
    gl: Gl,
    canvas: HtmlCanvasElement,
    gpu: Option<Gpu>,
    /// The toolpath in CPU memory, to upload again after a context loss.
    path: Lines,
    /// Where the stock is drawn this frame (W-CS on the table as it stands), if at all.
    stock_model: Option<DAffine3>,
    /// Where it was drawn in the last frame painted: what the pointer looks at.
    pub stock_shown: Option<DAffine3>,
    /// The stock drawn is still behind the one asked for: paint another frame.
    stock_behind: bool,
    /// Draw the stock cut open ([`schwenkbar_app::scene::pose::section_plane`]).
    pub section: bool,
    /// This frame's section plane (point, normal towards the viewer; W-CS), if any.
    stock_clip: Option<(glam::DVec3, glam::DVec3)>,
}

/// The WebGL2 context of a canvas. Multisampling is asked for (the browser may ignore it)
/// unless WebGL runs on the CPU: a classroom PC without a usable GPU, headless Chromium. There
/// 4× multisampling made every frame's paint the slowest part of a step (measured in the
/// browser suite on a 1,000,000-block program: a step 46 → 30 ms, the paint after the frame's
/// script 31–38 → 14–28 ms), while on a GPU it costs next to nothing.
pub fn context(canvas: &HtmlCanvasElement) -> Result<Gl, RenderError> {
    let attrs = js_sys::Object::new();
    let antialias = !web_sys::window().and_then(|w| w.document()).is_some_and(|d| webgl_on_cpu(&d));
    for (key, value) in [("antialias", antialias), ("alpha", false), ("premultipliedAlpha", false)] {
        js_sys::Reflect::set(&attrs, &JsValue::from_str(key), &JsValue::from_bool(value))
            .map_err(|_| RenderError::NoWebGl2)?;
    }
    match canvas.get_context_with_context_options("webgl2", &attrs) {
        Ok(Some(ctx)) => ctx.dyn_into::<Gl>().map_err(|_| RenderError::NoWebGl2),
        _ => Err(RenderError::NoWebGl2),
    }
}

/// Asks a throwaway canvas's context which renderer WebGL2 uses (a context's attributes are
/// fixed when it is made, so the answer is needed before the real one).
fn webgl_on_cpu(document: &web_sys::Document) -> bool {
    let Some(probe) =
        document.create_element("canvas").ok().and_then(|c| c.dyn_into::<HtmlCanvasElement>().ok())
    else {
        return false;
    };
    let Some(gl) = probe.get_context("webgl2").ok().flatten().and_then(|c| c.dyn_into::<Gl>().ok()) else {
        return false;
    };
    let on_cpu = software_renderer(&renderer_name(&gl));
    // Given back at once, not when the collector finds it: browsers cap the live contexts.
    if let Ok(Some(lose)) = gl.get_extension("WEBGL_lose_context")
        && let Ok(f) = js_sys::Reflect::get(&lose, &JsValue::from_str("loseContext"))
        && let Some(f) = f.dyn_ref::<js_sys::Function>()
    {
        let _ = f.call0(&lose);
    }
    on_cpu
}

/// The renderer's name: `UNMASKED_RENDERER_WEBGL` of `WEBGL_debug_renderer_info` where the
/// browser offers it, else `RENDERER` (often only "WebKit WebGL").
pub fn renderer_name(gl: &Gl) -> String {
    const UNMASKED_RENDERER_WEBGL: u32 = 0x9246;
    let pname = match gl.get_extension("WEBGL_debug_renderer_info") {
        Ok(Some(_)) => UNMASKED_RENDERER_WEBGL,
        _ => Gl::RENDERER,
    };
    gl.get_parameter(pname).ok().and_then(|v| v.as_string()).unwrap_or_default()
}

/// Whether a renderer name is one of the CPU rasterisers browsers fall back to: SwiftShader
/// (Chromium), llvmpipe and softpipe (Mesa, Firefox on Linux), WARP ("Microsoft Basic Render
/// Driver", Windows), Apple's software renderer.
#[must_use]
pub fn software_renderer(name: &str) -> bool {
    ["SwiftShader", "llvmpipe", "softpipe", "Basic Render Driver", "Software Renderer"]
        .iter()
        .any(|s| name.contains(s))
}

impl Renderer {
    pub fn new(canvas: &HtmlCanvasElement) -> Result<Renderer, RenderError> {
        let gl = context(canvas)?;
        let path = Lines::default();
        let gpu = Gpu::new(&gl, &path)?;
        Ok(Renderer {
            gl,
            canvas: canvas.clone(),
            gpu: Some(gpu),
            path,
            stock_model: None,
            stock_shown: None,
            stock_behind: false,
            section: false,
            stock_clip: None,
        })
    }

    /// The GL context (for tests and pixel probes).
    #[must_use]
    pub fn gl(&self) -> &Gl {
        &self.gl
    }

    /// The canvas drawn on.
    #[must_use]
    pub fn canvas(&self) -> &HtmlCanvasElement {
        &self.canvas
    }

    /// Replaces the toolpath (one upload; drawing it later costs one draw call).
    pub fn set_toolpath(&mut self, points: &[PathPoint]) -> Result<(), RenderError> {
        self.path = toolpath::lines(points);
        if let Some(gpu) = &mut self.gpu {
            gpu.toolpath = None;
            if !self.path.vertices.is_empty() {
                gpu.toolpath = Some(GpuLines::upload(&self.gl, &self.path)?);
            }
        }
        Ok(())
    }

    /// Whether the stock drawn is still behind the one asked for (the view paints again next
    /// frame, and the stock catches up a frame's share at a time).
    #[must_use]
    pub fn wants_frame(&self) -> bool {
        self.stock_behind
    }

    /// Forgets the GL objects of a lost context (they are invalid anyway).
    pub fn lost(&mut self) {
        self.gpu = None;
    }

    /// Rebuilds every GL object after `webglcontextrestored`.
    pub fn restore(&mut self) -> Result<(), RenderError> {
        self.gpu = None;
        self.gpu = Some(Gpu::new(&self.gl, &self.path)?);
        Ok(())
    }

    /// Matches the drawing buffer to the canvas' CSS size × devicePixelRatio; returns the CSS
    /// size. Cheap when nothing changed.
    pub fn fit(&self) -> (f32, f32) {
        let dpr = web_sys::window().map_or(1.0, |w| w.device_pixel_ratio()).clamp(0.5, 4.0);
        let (cw, ch) = (self.canvas.client_width().max(1), self.canvas.client_height().max(1));
        let (w, h) = ((f64::from(cw) * dpr).round() as u32, (f64::from(ch) * dpr).round() as u32);
        if self.canvas.width() != w || self.canvas.height() != h {
            self.canvas.set_width(w);
            self.canvas.set_height(h);
        }
        (cw as f32, ch as f32)
    }

    /// Draws a machine scene; returns its labels on screen.
    pub fn paint(&mut self, scene: &Scene<'_>, camera: &Camera) -> Result<Vec<ScreenLabel>, RenderError> {
        let list = triads::scene(scene, camera.elevation >= super::machine_parts::FROM_ABOVE);
        let s = scene.state;
        let p =
            schwenkbar_app::scene::pose::poses(scene.machine, &s.axes.rotary, s.axes.linear, s.tool.length);
        let wcs = DAffine3::from_mat3_translation(scene.state.wcs.rot, scene.state.wcs.origin);
        let path = (p.workpiece * wcs, scene.state.toolpath_drawn.unwrap_or(usize::MAX));
        self.stock_model = None;
        self.stock_behind = false;
        self.stock_clip = self
            .section
            .then(|| schwenkbar_app::scene::pose::section_plane(scene.machine, s, camera.eye().as_dvec3()));
        if let (Some(shape), Some(gpu)) = (&s.stock, &mut self.gpu) {
            // This frame's share of cutting towards the stock asked for; only changed tiles are
            // meshed and uploaded again.
            let (mesh, done) = shape.stock.mesh_toward(shape.step, shape.fraction, FRAME_RAYS);
            self.stock_behind = !done;
            let tiles = mesh.as_ref().map_or(&[][..], |m| m.tiles());
            gpu.stock.truncate(tiles.len());
            for (k, (_, tile)) in tiles.iter().enumerate() {
                if gpu.stock.get(k).is_some_and(|t| Rc::ptr_eq(&t.mesh, tile)) {
                    continue;
                }
                let (vertices, raw) = stock::vertices(tile);
                let up = StockTile {
                    mesh: tile.clone(),
                    tris: GpuTriangles::upload(&self.gl, &vertices)?,
                    raw,
                    all: vertices.len() / 6,
                };
                match gpu.stock.get_mut(k) {
                    Some(t) => *t = up,
                    None => gpu.stock.push(up),
                }
            }
            if mesh.is_some() {
                self.stock_model = Some(path.0);
            }
        }
        self.paint_list(&list, camera, Some(path))
    }

    /// Draws any draw list (the right-hand demo uses this directly), with the toolpath under
    /// `toolpath = (model, segments)` if given.
    pub fn paint_list(
        &mut self,
        list: &DrawList,
        camera: &Camera,
        toolpath: Option<(DAffine3, usize)>,
    ) -> Result<Vec<ScreenLabel>, RenderError> {
        let stock_model = self.stock_model.take();
        self.stock_shown = stock_model;
        let stock_clip = self.stock_clip.take();
        let gl = &self.gl;
        if gl.is_context_lost() {
            return Err(RenderError::ContextLost);
        }
        let Some(gpu) = &self.gpu else { return Err(RenderError::ContextLost) };
        let (css_w, css_h) = self.fit();
        let (w, h) = (self.canvas.width() as i32, self.canvas.height() as i32);
        gl.viewport(0, 0, w, h);
        gl.clear_color(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2], 1.0);
        gl.depth_mask(true);
        gl.clear(Gl::COLOR_BUFFER_BIT | Gl::DEPTH_BUFFER_BIT);
        gl.enable(Gl::DEPTH_TEST);
        gl.disable(Gl::CULL_FACE);
        gl.disable(Gl::BLEND);

        let aspect = css_w / css_h.max(1.0);
        let view = camera.view();
        let proj = camera.projection(aspect);

        gl.use_program(Some(&gpu.lit.program));
        gl.uniform_matrix4fv_with_f32_array(gpu.lit_u.projection.as_ref(), false, &proj.to_cols_array());
        draw_pass(gl, gpu, list, Pass::Opaque, &view);
        if let Some(model) = stock_model {
            let mv = view * mat4(&model);
            gl.uniform_matrix4fv_with_f32_array(gpu.lit_u.model_view.as_ref(), false, &mv.to_cols_array());
            if let Some((point, normal)) = stock_clip {
                // The plane carried into view space (a rigid motion: normals turn with it).
                let p = mv.transform_point3(point.as_vec3());
                let n = mv.transform_vector3(normal.as_vec3()).normalize_or_zero();
                gl.uniform4f(gpu.lit_u.clip.as_ref(), n.x, n.y, n.z, -n.dot(p));
            }
            gl.uniform4f(gpu.lit_u.inside.as_ref(), CUT[0], CUT[1], CUT[2], 1.0);
            gl.uniform4f(gpu.lit_u.colour.as_ref(), BLANK[0], BLANK[1], BLANK[2], 1.0);
            // A hundredth of a millimetre or so towards the eye: the tool tip's path lies in the
            // face it cut, and drawn after it the line showed in dashes where the two depths
            // happened to round apart; now the face hides it (the path above the part stays).
            gl.enable(Gl::POLYGON_OFFSET_FILL);
            gl.polygon_offset(-1.0, -32.0);
            for t in &gpu.stock {
                t.tris.draw(0, t.raw);
            }
            gl.uniform4f(gpu.lit_u.colour.as_ref(), CUT[0], CUT[1], CUT[2], 1.0);
            for t in &gpu.stock {
                t.tris.draw(t.raw, t.all - t.raw);
            }
            gl.disable(Gl::POLYGON_OFFSET_FILL);
            gl.uniform4f(gpu.lit_u.clip.as_ref(), 0.0, 0.0, 0.0, 0.0);
            gl.uniform4f(gpu.lit_u.inside.as_ref(), 0.0, 0.0, 0.0, 0.0);
        }

        if let (Some(lines), Some((model, segments))) = (&gpu.toolpath, toolpath) {
            gl.use_program(Some(&gpu.line.program));
            let mvp = proj * view * mat4(&model);
            gl.uniform_matrix4fv_with_f32_array(gpu.line_mvp.as_ref(), false, &mvp.to_cols_array());
            lines.draw(segments);
            gl.use_program(Some(&gpu.lit.program));
        }

        gl.enable(Gl::BLEND);
        gl.blend_func(Gl::SRC_ALPHA, Gl::ONE_MINUS_SRC_ALPHA);
        gl.depth_mask(false);
        // Pulled towards the eye (a fraction of a millimetre at the usual distance): a
        // translucent surface that lies in an opaque one (the working plane in the blank's top
        // face whenever the preset is on it; the other candidate's ghost where its part turned
        // into itself) drew over part of it only, in stripes where the two depths happened to
        // round apart.
        gl.enable(Gl::POLYGON_OFFSET_FILL);
        gl.polygon_offset(-4.0, -256.0);
        draw_pass(gl, gpu, list, Pass::Translucent, &view);
        gl.disable(Gl::POLYGON_OFFSET_FILL);
        gl.disable(Gl::DEPTH_TEST);
        draw_pass(gl, gpu, list, Pass::XRay, &view);
        gl.enable(Gl::DEPTH_TEST);
        gl.disable(Gl::BLEND);
        gl.depth_mask(true);

        // Triads on top: a fresh depth buffer, so they hide each other correctly but nothing
        // of the machine hides them.
        gl.clear(Gl::DEPTH_BUFFER_BIT);
        draw_pass(gl, gpu, list, Pass::Overlay, &view);

        let view_proj = camera.view_proj(aspect);
        Ok(list
            .labels
            .iter()
            .filter_map(|l| {
                let (x, y) = project_to_css(&view_proj, l.at.as_vec3(), css_w, css_h)?;
                Some(ScreenLabel { text: l.text, kind: l.kind, x, y })
            })
            .collect())
    }
}

/// A part's placement for the GPU. The scene is built in f64 (kinematics), drawn in f32: a few
/// metres at 1e-7 relative precision is far below a pixel, and one matrix type keeps the wasm
/// small.
fn mat4(a: &DAffine3) -> Mat4 {
    let m = a.matrix3.as_mat3();
    Mat4::from_cols(
        m.x_axis.extend(0.0),
        m.y_axis.extend(0.0),
        m.z_axis.extend(0.0),
        a.translation.as_vec3().extend(1.0),
    )
}

fn draw_pass(gl: &Gl, gpu: &Gpu, list: &DrawList, pass: Pass, view: &Mat4) {
    for inst in list.instances.iter().filter(|i| i.pass == pass) {
        let mv = *view * mat4(&inst.model);
        // A flat part (zero scale) has no normals to shade with (the shader inverts this matrix).
        if Mat3::from_mat4(mv).determinant().abs() < 1e-9 {
            continue;
        }
        gl.uniform_matrix4fv_with_f32_array(gpu.lit_u.model_view.as_ref(), false, &mv.to_cols_array());
        let c = inst.colour;
        gl.uniform4f(gpu.lit_u.colour.as_ref(), c[0], c[1], c[2], c[3]);
        if let Some(mesh) = gpu.shapes.get(inst.shape as usize) {
            mesh.draw();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::software_renderer;

    /// Names as browsers report them (`UNMASKED_RENDERER_WEBGL`).
    #[test]
    fn cpu_rasterisers_are_told_from_gpus() {
        for cpu in [
            "ANGLE (Google, Vulkan 1.3.0 (SwiftShader Device (Subzero) (0x0000C0DE)), SwiftShader driver)",
            "Google SwiftShader",
            "llvmpipe (LLVM 15.0.6, 256 bits)",
            "ANGLE (Microsoft, Microsoft Basic Render Driver Direct3D11 vs_5_0 ps_5_0, D3D11)",
            "Apple Software Renderer",
        ] {
            assert!(software_renderer(cpu), "{cpu}");
        }
        for gpu in [
            "ANGLE (Intel, Intel(R) UHD Graphics 620 Direct3D11 vs_5_0 ps_5_0, D3D11)",
            "ANGLE (NVIDIA, NVIDIA GeForce GTX 1650 (0x00001F82) Direct3D11 vs_5_0 ps_5_0, D3D11)",
            "Mesa Intel(R) UHD Graphics 620 (KBL GT2)",
            "Apple M1",
            "WebKit WebGL",
            "",
        ] {
            assert!(!software_renderer(gpu), "{gpu}");
        }
    }
}
