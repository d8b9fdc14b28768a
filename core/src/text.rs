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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn latin1_umlauts_are_decoded_and_written_back() {
        assert_eq!(decode(b"; r\xfccksetzen".to_vec()), "; rücksetzen");
        assert_eq!(decode("; rücksetzen".as_bytes().to_vec()), "; rücksetzen");
        assert_eq!(encode_latin1("; rücksetzen €"), b"; r\xfccksetzen ?".to_vec());
    }
}
