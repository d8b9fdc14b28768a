//! Reading NC files: the control writes ANSI (Latin-1), so bytes that are not UTF-8 are
//! decoded as Latin-1 instead of being refused.

use std::path::Path;

/// UTF-8 if the file is valid UTF-8, else Latin-1 (every byte is the code point of the same value).
pub(crate) fn decode(bytes: Vec<u8>) -> String {
    match String::from_utf8(bytes) {
        Ok(s) => s,
        Err(e) => e.into_bytes().iter().map(|&b| char::from(b)).collect(),
    }
}

pub(crate) fn read(path: &Path) -> Result<String, String> {
    std::fs::read(path).map(decode).map_err(|e| format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::decode;

    #[test]
    fn latin1_umlauts_are_decoded() {
        assert_eq!(decode(b"; r\xfccksetzen".to_vec()), "; rücksetzen");
        assert_eq!(decode("; rücksetzen".as_bytes().to_vec()), "; rücksetzen");
    }
}
