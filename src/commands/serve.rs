//! `garmentcode serve [--port P] [--host H]`: the web configurator.

use crate::cli::ServeArgs;
use crate::commands::CliError;
use crate::web::{http::Limits, server};

pub fn run(args: ServeArgs) -> Result<i32, CliError> {
    let (host, port) = (args.host.as_str(), args.port);
    let listener = server::bind(host, port).map_err(|e| {
        let hint = if e.kind() == std::io::ErrorKind::AddrInUse { " (choose another with --port; --port 0 picks a free one)" } else { "" };
        CliError::Input(format!("cannot listen on {host}:{port}: {e}{hint}"))
    })?;
    let addr = listener.local_addr().map_err(|e| CliError::Input(format!("cannot listen on {host}:{port}: {e}")))?;
    if !server::is_loopback(&addr) {
        eprintln!("warning: listening on {addr}: the configurator is reachable from other machines");
    }
    if addr.ip().is_unspecified() {
        outln!(
            "Serving the garment configurator at {} (and at this machine's addresses, port {}; Ctrl-C to stop)",
            server::url(&addr),
            addr.port()
        );
    } else {
        outln!("Serving the garment configurator at {} (Ctrl-C to stop)", server::url(&addr));
    }
    server::serve(listener, Limits::default(), log).map_err(|e| CliError::Failed(format!("the server stopped: {e}")))?;
    eprintln!("stopped");
    Ok(0)
}

/// A log line on stderr; a closed stderr is ignored (never a panic).
fn log(line: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "{line}");
}
