//! `garmentcode serve [--port P] [--host H]`: the web configurator.

use crate::args::{Args, UsageError};
use crate::commands::CliError;
use garmentcode_cli::web::{http::Limits, server};

/// Port used without `--port`.
pub const DEFAULT_PORT: u16 = 8000;

pub fn run(mut args: Args) -> Result<i32, CliError> {
    let port = match args.value("port")? {
        None => DEFAULT_PORT,
        Some(p) => p.parse::<u16>().map_err(|_| UsageError(format!("serve --port: expected a port number from 0 to 65535, got '{p}'")))?,
    };
    let host = args.value("host")?.unwrap_or_else(|| "127.0.0.1".into());
    let rest = args.finish()?;
    if !rest.is_empty() {
        return Err(UsageError(format!("serve: unexpected argument '{}'", rest[0])).into());
    }
    let listener = server::bind(&host, port).map_err(|e| {
        let hint = if e.kind() == std::io::ErrorKind::AddrInUse { " (choose another with --port; --port 0 picks a free one)" } else { "" };
        CliError::Input(format!("cannot listen on {host}:{port}: {e}{hint}"))
    })?;
    let addr = listener.local_addr().map_err(|e| CliError::Input(format!("cannot listen on {host}:{port}: {e}")))?;
    if !server::is_loopback(&addr) {
        eprintln!("warning: listening on {addr}: the configurator is reachable from other machines");
    }
    outln!("Serving the garment configurator at {} (Ctrl-C to stop)", server::url(&addr));
    server::serve(listener, Limits::default(), |line| eprintln!("{line}"));
    Ok(0)
}
