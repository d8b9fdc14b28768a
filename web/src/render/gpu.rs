//! GL resources that free themselves: shader programs, meshes (VAO + vertex and index buffers)
//! and line sets. Each holds a handle to its context so `Drop` can delete it; uploads happen once,
//! at creation.

use js_sys::{Float32Array, Uint32Array};
use web_sys::{
    WebGl2RenderingContext as Gl, WebGlBuffer, WebGlProgram, WebGlShader, WebGlUniformLocation,
    WebGlVertexArrayObject,
};

use super::mesh::{Lines, Mesh};

/// Why the renderer could not start or draw.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum RenderError {
    /// The browser gives no WebGL2 context.
    NoWebGl2,
    /// The context is lost (the GPU was reset); it comes back with `webglcontextrestored`.
    ContextLost,
    /// A shader did not compile or link (the driver's log).
    Shader(String),
    /// GL refused to create an object.
    Resource(&'static str),
}

impl std::fmt::Display for RenderError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            RenderError::NoWebGl2 => write!(f, "no WebGL2"),
            RenderError::ContextLost => write!(f, "WebGL context lost"),
            RenderError::Shader(log) => write!(f, "shader: {log}"),
            RenderError::Resource(what) => write!(f, "could not create {what}"),
        }
    }
}

impl std::error::Error for RenderError {}

fn shader(gl: &Gl, kind: u32, source: &str) -> Result<WebGlShader, RenderError> {
    let s = gl.create_shader(kind).ok_or(RenderError::Resource("shader"))?;
    gl.shader_source(&s, source);
    gl.compile_shader(&s);
    if gl.get_shader_parameter(&s, Gl::COMPILE_STATUS).as_bool() == Some(true) {
        Ok(s)
    } else {
        let log = gl.get_shader_info_log(&s).unwrap_or_default();
        gl.delete_shader(Some(&s));
        Err(if gl.is_context_lost() { RenderError::ContextLost } else { RenderError::Shader(log) })
    }
}

/// A linked program with its uniform locations looked up once.
pub struct Program {
    gl: Gl,
    pub program: WebGlProgram,
}

impl Program {
    pub fn new(gl: &Gl, vert: &str, frag: &str) -> Result<Program, RenderError> {
        let v = shader(gl, Gl::VERTEX_SHADER, vert)?;
        let f = shader(gl, Gl::FRAGMENT_SHADER, frag)?;
        let program = gl.create_program().ok_or(RenderError::Resource("program"))?;
        gl.attach_shader(&program, &v);
        gl.attach_shader(&program, &f);
        gl.link_program(&program);
        // The shaders are no longer needed once linked (or failed).
        gl.delete_shader(Some(&v));
        gl.delete_shader(Some(&f));
        if gl.get_program_parameter(&program, Gl::LINK_STATUS).as_bool() == Some(true) {
            Ok(Program { gl: gl.clone(), program })
        } else {
            let log = gl.get_program_info_log(&program).unwrap_or_default();
            gl.delete_program(Some(&program));
            Err(if gl.is_context_lost() { RenderError::ContextLost } else { RenderError::Shader(log) })
        }
    }

    /// A uniform's location (`None` if the compiler removed it; setting it is then a no-op).
    #[must_use]
    pub fn uniform(&self, name: &str) -> Option<WebGlUniformLocation> {
        self.gl.get_uniform_location(&self.program, name)
    }
}

impl Drop for Program {
    fn drop(&mut self) {
        self.gl.delete_program(Some(&self.program));
    }
}

fn buffer(gl: &Gl) -> Result<WebGlBuffer, RenderError> {
    gl.create_buffer().ok_or(RenderError::Resource("buffer"))
}

fn vertex_array(gl: &Gl) -> Result<WebGlVertexArrayObject, RenderError> {
    gl.create_vertex_array().ok_or(RenderError::Resource("vertex array"))
}

/// Two float attributes of 3 components each, interleaved (position + normal, or + colour).
fn interleaved_3_3(gl: &Gl) {
    const STRIDE: i32 = 6 * 4;
    gl.enable_vertex_attrib_array(0);
    gl.vertex_attrib_pointer_with_i32(0, 3, Gl::FLOAT, false, STRIDE, 0);
    gl.enable_vertex_attrib_array(1);
    gl.vertex_attrib_pointer_with_i32(1, 3, Gl::FLOAT, false, STRIDE, 3 * 4);
}

/// A triangle mesh on the GPU.
pub struct GpuMesh {
    gl: Gl,
    vao: WebGlVertexArrayObject,
    vbo: WebGlBuffer,
    ibo: WebGlBuffer,
    count: i32,
}

impl GpuMesh {
    pub fn upload(gl: &Gl, mesh: &Mesh) -> Result<GpuMesh, RenderError> {
        let (vao, vbo, ibo) = (vertex_array(gl)?, buffer(gl)?, buffer(gl)?);
        gl.bind_vertex_array(Some(&vao));
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&vbo));
        gl.buffer_data_with_array_buffer_view(
            Gl::ARRAY_BUFFER,
            &Float32Array::from(mesh.vertices.as_slice()),
            Gl::STATIC_DRAW,
        );
        interleaved_3_3(gl);
        gl.bind_buffer(Gl::ELEMENT_ARRAY_BUFFER, Some(&ibo));
        gl.buffer_data_with_array_buffer_view(
            Gl::ELEMENT_ARRAY_BUFFER,
            &Uint32Array::from(mesh.indices.as_slice()),
            Gl::STATIC_DRAW,
        );
        gl.bind_vertex_array(None);
        let count = i32::try_from(mesh.indices.len()).map_err(|_| RenderError::Resource("index count"))?;
        Ok(GpuMesh { gl: gl.clone(), vao, vbo, ibo, count })
    }

    pub fn draw(&self) {
        self.gl.bind_vertex_array(Some(&self.vao));
        self.gl.draw_elements_with_i32(Gl::TRIANGLES, self.count, Gl::UNSIGNED_INT, 0);
    }
}

impl Drop for GpuMesh {
    fn drop(&mut self) {
        self.gl.delete_vertex_array(Some(&self.vao));
        self.gl.delete_buffer(Some(&self.vbo));
        self.gl.delete_buffer(Some(&self.ibo));
    }
}

/// Triangles without indices (the stock): one static buffer of position + normal, drawn in
/// ranges.
pub struct GpuTriangles {
    gl: Gl,
    vao: WebGlVertexArrayObject,
    vbo: WebGlBuffer,
}

impl GpuTriangles {
    pub fn upload(gl: &Gl, vertices: &[f32]) -> Result<GpuTriangles, RenderError> {
        let (vao, vbo) = (vertex_array(gl)?, buffer(gl)?);
        gl.bind_vertex_array(Some(&vao));
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&vbo));
        gl.buffer_data_with_array_buffer_view(
            Gl::ARRAY_BUFFER,
            &Float32Array::from(vertices),
            Gl::STATIC_DRAW,
        );
        interleaved_3_3(gl);
        gl.bind_vertex_array(None);
        Ok(GpuTriangles { gl: gl.clone(), vao, vbo })
    }

    /// Draws vertices `first..first + count`.
    pub fn draw(&self, first: usize, count: usize) {
        if let (Ok(first), Ok(count)) = (i32::try_from(first), i32::try_from(count))
            && count > 0
        {
            self.gl.bind_vertex_array(Some(&self.vao));
            self.gl.draw_arrays(Gl::TRIANGLES, first, count);
        }
    }
}

impl Drop for GpuTriangles {
    fn drop(&mut self) {
        self.gl.delete_vertex_array(Some(&self.vao));
        self.gl.delete_buffer(Some(&self.vbo));
    }
}

/// Coloured line segments on the GPU (the toolpath): one static buffer.
pub struct GpuLines {
    gl: Gl,
    vao: WebGlVertexArrayObject,
    vbo: WebGlBuffer,
    vertices: i32,
}

impl GpuLines {
    pub fn upload(gl: &Gl, lines: &Lines) -> Result<GpuLines, RenderError> {
        let (vao, vbo) = (vertex_array(gl)?, buffer(gl)?);
        gl.bind_vertex_array(Some(&vao));
        gl.bind_buffer(Gl::ARRAY_BUFFER, Some(&vbo));
        gl.buffer_data_with_array_buffer_view(
            Gl::ARRAY_BUFFER,
            &Float32Array::from(lines.vertices.as_slice()),
            Gl::STATIC_DRAW,
        );
        interleaved_3_3(gl);
        gl.bind_vertex_array(None);
        let vertices =
            i32::try_from(lines.vertex_count()).map_err(|_| RenderError::Resource("line count"))?;
        Ok(GpuLines { gl: gl.clone(), vao, vbo, vertices })
    }

    /// Draws the first `segments` segments (all if more are asked for).
    pub fn draw(&self, segments: usize) {
        let n = i32::try_from(segments.saturating_mul(2)).unwrap_or(i32::MAX).min(self.vertices);
        if n > 0 {
            self.gl.bind_vertex_array(Some(&self.vao));
            self.gl.draw_arrays(Gl::LINES, 0, n);
        }
    }
}

impl Drop for GpuLines {
    fn drop(&mut self) {
        self.gl.delete_vertex_array(Some(&self.vao));
        self.gl.delete_buffer(Some(&self.vbo));
    }
}
