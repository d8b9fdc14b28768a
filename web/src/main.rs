fn main() {
    schwenkbar_web::start();
}
