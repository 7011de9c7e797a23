//! `povrayst`: render, check and format POV-Ray scenes, and run the language server.

fn main() {
    eprintln!("povrayst: no commands yet");
    std::process::exit(2);
}
