//! CSV as RFC 4180 writes it, for every CSV placecat reads or writes (labels,
//! categories, distances, poses): one quoting rule and one parser, so that
//! what one part writes another reads back unchanged.
//!
//! Writing: a cell is quoted when it holds a comma, a double quote, a CR or
//! an LF; a quote inside is doubled. Reading: commas inside quotes, doubled
//! quotes, line breaks inside quotes, CRLF or LF line ends, a UTF-8 byte
//! order mark at the start (spreadsheets write one), and a last line with
//! or without its line end. Lenient where RFC 4180 is silent and nothing
//! can be misread: a quote inside a cell that does not start with one is
//! kept as a character (`5" disk`), and empty lines are skipped (they hold
//! no cell). An unclosed quote, or text after a closing quote, is an error
//! naming the line: guessing there would silently join or split cells.

use crate::error::{Error, Result};
use std::borrow::Cow;

/// One record and the line of the text it starts on (1-based), for errors.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Record {
    /// The line the record starts on, 1-based.
    pub line: usize,
    /// Its cells, unquoted.
    pub cells: Vec<String>,
}

/// The cell as written in CSV: quoted when it must be, else as is.
pub fn quote(cell: &str) -> Cow<'_, str> {
    if cell.contains([',', '"', '\r', '\n']) {
        Cow::Owned(format!("\"{}\"", cell.replace('"', "\"\"")))
    } else {
        Cow::Borrowed(cell)
    }
}

/// One record: the cells quoted and joined by commas, no line end.
pub fn record<S: AsRef<str>>(cells: impl IntoIterator<Item = S>) -> String {
    let mut out = String::new();
    for (i, c) in cells.into_iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push_str(&quote(c.as_ref()));
    }
    out
}

/// Every record of a CSV text (see the module notes for what is accepted).
pub fn parse(text: &str) -> Result<Vec<Record>> {
    parse_from(text, 1)
}

/// [`parse`] of a text that starts on line `first` of its file.
fn parse_from(text: &str, first: usize) -> Result<Vec<Record>> {
    let text = text.strip_prefix('\u{feff}').unwrap_or(text);
    let mut records = Vec::new();
    let mut chars = text.chars().peekable();
    let mut line = first;
    while chars.peek().is_some() {
        let start = line;
        let mut cells = vec![String::new()];
        // Within one record; ends at a line break outside quotes or the end.
        loop {
            let cell = cells.last_mut().expect("one cell at least");
            match chars.next() {
                None => break,
                Some('"') if cell.is_empty() => {
                    let open = line;
                    loop {
                        match chars.next() {
                            None => {
                                return Err(Error::Csv(format!(
                                    "line {open}: a quote opened here is not closed"
                                )))
                            }
                            Some('"') if chars.peek() == Some(&'"') => {
                                chars.next();
                                cell.push('"');
                            }
                            Some('"') => break,
                            Some(c) => {
                                if c == '\n' {
                                    line += 1;
                                }
                                cell.push(c);
                            }
                        }
                    }
                    match chars.peek() {
                        None | Some(',') | Some('\r') | Some('\n') => {}
                        Some(_) => {
                            return Err(Error::Csv(format!(
                                "line {line}: text after the closing quote of a cell (a quote inside a quoted cell is written \"\")"
                            )))
                        }
                    }
                }
                Some(',') => cells.push(String::new()),
                Some('\r') if chars.peek() == Some(&'\n') => {}
                Some('\n') => {
                    line += 1;
                    break;
                }
                Some(c) => cell.push(c),
            }
        }
        // An empty line holds no cell; skipping it loses nothing.
        if cells.len() > 1 || !cells[0].is_empty() {
            records.push(Record { line: start, cells });
        }
    }
    Ok(records)
}

/// The cells of `line`, line `lineno` of its file, that holds exactly one
/// record (for formats read line by line, where a line break inside quotes
/// cannot be); errors name `lineno`.
pub fn parse_line(line: &str, lineno: usize) -> Result<Vec<String>> {
    let mut records = parse_from(line, lineno)?;
    match records.len() {
        0 => Ok(vec![String::new()]),
        1 => Ok(records.pop().expect("one").cells),
        _ => Err(Error::Csv(format!(
            "line {lineno}: a line break inside one line"
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Names a user can give files and categories, each hostile to a
    /// naive CSV in its own way.
    const HOSTILE: [&str; 12] = [
        "room",
        "lab, \"wet\"",
        "\"quoted\"",
        "a,b,c",
        "two\nlines",
        "crlf\r\ninside",
        "",
        " padded ",
        "5\" disk",
        "Küche, 2. OG",
        "会议室",
        "emoji 🛋️,\"x\"",
    ];

    #[test]
    fn hostile_names_round_trip_to_identical_bytes() {
        let rows: Vec<Vec<String>> = HOSTILE
            .chunks(3)
            .map(|c| c.iter().map(|s| s.to_string()).collect())
            .collect();
        let write = |rows: &[Vec<String>]| -> String {
            rows.iter().map(|r| record(r) + "\r\n").collect::<String>()
        };
        let text = write(&rows);
        let back: Vec<Vec<String>> = parse(&text).unwrap().into_iter().map(|r| r.cells).collect();
        assert_eq!(back, rows);
        // Export, import, export again: the same bytes.
        assert_eq!(write(&back), text);
        // And with LF line ends, a BOM, no final line end.
        let lines: Vec<String> = rows.iter().map(record).collect();
        let lf = format!("\u{feff}{}", lines.join("\n"));
        let back: Vec<Vec<String>> = parse(&lf).unwrap().into_iter().map(|r| r.cells).collect();
        assert_eq!(back, rows);
    }

    #[test]
    fn quoting_is_only_where_needed() {
        assert_eq!(quote("room"), "room");
        assert_eq!(quote("Küche"), "Küche");
        assert_eq!(quote("lab, \"wet\""), "\"lab, \"\"wet\"\"\"");
        assert_eq!(quote("a\nb"), "\"a\nb\"");
        assert_eq!(record(["a,b", "c"]), "\"a,b\",c");
    }

    #[test]
    fn records_know_their_lines_and_skip_empty_ones() {
        let text = "\u{feff}file,label\r\n\r\n\"a\nb.ply\",x\nc.ply,\"y,z\"\n";
        let r = parse(text).unwrap();
        assert_eq!(
            r,
            vec![
                Record {
                    line: 1,
                    cells: vec!["file".into(), "label".into()]
                },
                Record {
                    line: 3,
                    cells: vec!["a\nb.ply".into(), "x".into()]
                },
                Record {
                    line: 5,
                    cells: vec!["c.ply".into(), "y,z".into()]
                },
            ]
        );
        assert_eq!(parse_line("a,,\"\"", 1).unwrap(), ["a", "", ""]);
        assert_eq!(parse_line("5\" disk,x", 1).unwrap(), ["5\" disk", "x"]);
    }

    #[test]
    fn unclosed_quotes_and_text_after_a_quote_are_errors_naming_the_line() {
        let e = parse("a,b\nc,\"open\nd,e\n").unwrap_err().to_string();
        assert_eq!(e, "CSV: line 2: a quote opened here is not closed");
        let e = parse("a,b\n\"lab, \"\"wet\"\"\"\n\"lab, \"wet\"\"\n")
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("CSV: line 3: text after the closing quote"),
            "{e}"
        );
        assert!(parse_line("a\nb", 7).is_err());
        let e = parse_line("\"a,b", 7).unwrap_err().to_string();
        assert_eq!(e, "CSV: line 7: a quote opened here is not closed");
    }
}
