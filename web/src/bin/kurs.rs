//! Entry point of the course page (`kurs.html`).

fn main() {
    schwenkbar_web::start_course();
}
