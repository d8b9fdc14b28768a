//! Entry point of the machine editor page (`maschine.html`).

fn main() {
    schwenkbar_web::start_editor();
}
