//! NC files as bytes: the control writes ANSI (Latin-1), so bytes that are not UTF-8 are read
//! as Latin-1 instead of being refused, and programs are written back as Latin-1.

/// UTF-8 if `bytes` are valid UTF-8, else Latin-1 (every byte is the code point of its value).
#[must_use]
pub fn decode(bytes: Vec<u8>) -> String {
    match String::from_utf8(bytes) {
        Ok(s) => s,
        Err(e) => e.into_bytes().iter().map(|&b| char::from(b)).collect(),
    }
}

/// Latin-1 bytes for the control; a character outside Latin-1 becomes `?`.
#[must_use]
pub fn encode_latin1(text: &str) -> Vec<u8> {
    text.chars().map(|c| u8::try_from(u32::from(c)).unwrap_or(b'?')).collect()
}

/// Whether `bytes` are not a text file at all (an image, a CAD model, an archive): a NUL byte,
/// or more than one in 20 of the first 4 KiB a control character other than tab, line feed,
/// form feed and carriage return. Klartext programs are Latin-1 or UTF-8 text, where neither
/// happens; a Latin-1 umlaut is above 0x7F and counts as text.
#[must_use]
pub fn looks_binary(bytes: &[u8]) -> bool {
    let head = &bytes[..bytes.len().min(4096)];
    let control = head.iter().filter(|&&b| b < 0x20 && !matches!(b, b'\t' | b'\n' | 0x0c | b'\r')).count();
    head.contains(&0) || control * 20 > head.len()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn binary_files_are_told_from_programs() {
        let png = b"\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\x01\0";
        assert!(looks_binary(png));
        let gzip: Vec<u8> = [0x1f, 0x8b, 0x08, 0x00].iter().copied().cycle().take(400).collect();
        assert!(looks_binary(&gzip));
        let control: Vec<u8> = (1u8..32).chain(b"L X+1 ".iter().copied()).cycle().take(400).collect();
        assert!(looks_binary(&control), "control characters without a NUL");
        assert!(!looks_binary(b"0 BEGIN PGM X MM\r\n1 L Z+0 R0 FMAX M91 ; r\xfccksetzen\n\x0c"));
        assert!(!looks_binary(b""));
        let program =
            std::fs::read(concat!(env!("CARGO_MANIFEST_DIR"), "/../static/programs/musterprogramm1.h"))
                .expect("the shipped sample");
        assert!(!looks_binary(&program));
    }

    #[test]
    fn latin1_umlauts_are_decoded_and_written_back() {
        assert_eq!(decode(b"; r\xfccksetzen".to_vec()), "; rücksetzen");
        assert_eq!(decode("; rücksetzen".as_bytes().to_vec()), "; rücksetzen");
        assert_eq!(encode_latin1("; rücksetzen €"), b"; r\xfccksetzen ?".to_vec());
    }
}
