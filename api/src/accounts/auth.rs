//! Who a bearer token belongs to ([`Caller`]), and the tokens file that names the accounts, their
//! tokens and limits. The admin token (`--token`) sees everything; account tokens
//! (`--tokens-file`) see only their own account's captures and jobs. Comparisons run in time
//! independent of where the tokens differ. The routes are guarded by
//! [`crate::http::token_guard`].

use std::path::Path;

use crate::accounts::limits::AccountLimits;

/// Constant-time equality of two byte strings (length is not secret).
fn same_token(given: &[u8], expected: &[u8]) -> bool {
    given.len() == expected.len()
        && given
            .iter()
            .zip(expected)
            .fold(0u8, |acc, (a, b)| acc | (a ^ b))
            == 0
}

/// Who sent a request, from its bearer token (a request extension of every guarded route).
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Caller {
    /// The admin token, or anyone when the service has no tokens: sees every record.
    Admin,
    /// An account's token: sees only that account's captures and jobs.
    Account(String),
}

impl Caller {
    /// The account new records belong to (`None` for the admin).
    pub fn account(&self) -> Option<&str> {
        match self {
            Caller::Admin => None,
            Caller::Account(name) => Some(name),
        }
    }

    /// Whether a record of `owner` is visible to this caller.
    pub fn may_see(&self, owner: Option<&str>) -> bool {
        match self {
            Caller::Admin => true,
            Caller::Account(name) => owner == Some(name.as_str()),
        }
    }
}

/// One account's token, and the limits the tokens file gives the account.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct AccountToken {
    pub account: String,
    pub token: String,
    /// Its own limits; those it does not set are the server's defaults
    /// ([`crate::accounts::limits`]).
    pub limits: AccountLimits,
}

impl AccountToken {
    /// An account's token with the server's default limits.
    pub fn new(account: &str, token: &str) -> AccountToken {
        AccountToken {
            account: account.to_owned(),
            token: token.to_owned(),
            limits: AccountLimits::default(),
        }
    }
}

/// A tokens file that cannot be used.
#[derive(Debug, thiserror::Error)]
pub enum TokensFileError {
    #[error("cannot read the tokens file `{path}`: {source}")]
    Io {
        path: std::path::PathBuf,
        source: std::io::Error,
    },
    #[error("tokens file line {line}: {problem}")]
    Line { line: usize, problem: String },
}

/// Fewest characters of any token, the admin's and the accounts'.
pub const MIN_TOKEN_CHARS: usize = 16;

/// Reads a tokens file: one `ACCOUNT TOKEN [LIMIT=VALUE …]` a line (account names of
/// `[A-Za-z0-9._-]`, tokens of at least [`MIN_TOKEN_CHARS`] characters, each once; limits
/// `max_running`, `max_queued`, `max_storage_mb`, `max_priority`); blank lines and `#` comments
/// are skipped.
pub fn read_tokens_file(path: &Path) -> Result<Vec<AccountToken>, TokensFileError> {
    let text = std::fs::read_to_string(path).map_err(|source| TokensFileError::Io {
        path: path.to_owned(),
        source,
    })?;
    parse_tokens(&text)
}

fn parse_tokens(text: &str) -> Result<Vec<AccountToken>, TokensFileError> {
    let mut tokens: Vec<AccountToken> = Vec::new();
    for (index, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let bad = |problem: &str| TokensFileError::Line {
            line: index + 1,
            problem: problem.to_owned(),
        };
        let mut words = line.split_whitespace();
        let (Some(account), Some(token)) = (words.next(), words.next()) else {
            return Err(bad("expected `ACCOUNT TOKEN [LIMIT=VALUE …]`"));
        };
        let mut limits = AccountLimits::default();
        for word in words {
            limits.set(word).map_err(|problem| bad(&problem))?;
        }
        let valid_name = |c: char| c.is_ascii_alphanumeric() || matches!(c, '.' | '_' | '-');
        if account.len() > 64 || !account.chars().all(valid_name) {
            return Err(bad("account names are 1 to 64 of A-Z a-z 0-9 . _ -"));
        }
        if token.chars().count() < MIN_TOKEN_CHARS {
            return Err(bad(&format!(
                "tokens need at least {MIN_TOKEN_CHARS} characters"
            )));
        }
        if tokens
            .iter()
            .any(|t| t.token == token || t.account == account)
        {
            return Err(bad("each account and each token may appear once"));
        }
        tokens.push(AccountToken {
            limits,
            ..AccountToken::new(account, token)
        });
    }
    Ok(tokens)
}

/// The caller a bearer token names: the admin, an account, or `None` (unknown token).
pub fn caller_of(token: &str, admin: Option<&str>, accounts: &[AccountToken]) -> Option<Caller> {
    let admin_matches = admin.is_some_and(|a| same_token(token.as_bytes(), a.as_bytes()));
    // Every account token is compared, so the time does not tell which one matched.
    let account = accounts.iter().fold(None, |found, a| {
        if same_token(token.as_bytes(), a.token.as_bytes()) {
            Some(a.account.clone())
        } else {
            found
        }
    });
    match (admin_matches, account) {
        (true, _) => Some(Caller::Admin),
        (false, Some(name)) => Some(Caller::Account(name)),
        (false, None) => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn tokens_name_their_callers() {
        let accounts = parse_tokens(
            "# studio accounts\nalice  aaaaaaaaaaaaaaaa-1\n\nbob bbbbbbbbbbbbbbbb-2 max_running=1 \
             max_storage_mb=512\n",
        )
        .unwrap();
        assert_eq!(accounts.len(), 2);
        assert_eq!(accounts[0].limits, AccountLimits::default());
        let bobs = accounts[1].limits;
        assert_eq!(
            (bobs.max_running, bobs.max_storage_bytes),
            (Some(1), Some(512 << 20))
        );
        let admin = Some("admin-token-xxxxxxxx");
        assert_eq!(
            caller_of("admin-token-xxxxxxxx", admin, &accounts),
            Some(Caller::Admin)
        );
        assert_eq!(
            caller_of("bbbbbbbbbbbbbbbb-2", admin, &accounts),
            Some(Caller::Account("bob".into()))
        );
        assert_eq!(caller_of("bbbbbbbbbbbbbbbb-3", admin, &accounts), None);
        assert_eq!(caller_of("x", None, &[]), None);
        let bob = Caller::Account("bob".into());
        assert!(bob.may_see(Some("bob")) && !bob.may_see(Some("alice")) && !bob.may_see(None));
        assert!(Caller::Admin.may_see(Some("alice")) && Caller::Admin.may_see(None));
    }

    #[test]
    fn bad_tokens_files_name_the_line() {
        for (text, line) in [
            ("alice short", 1),
            ("# c\nalice aaaaaaaaaaaaaaaa extra", 2),
            ("alice aaaaaaaaaaaaaaaa max_queued=many", 1),
            ("alice aaaaaaaaaaaaaaaa\nalice bbbbbbbbbbbbbbbb", 2),
            ("alice aaaaaaaaaaaaaaaa\nbob aaaaaaaaaaaaaaaa", 2),
            ("al/ice aaaaaaaaaaaaaaaa", 1),
        ] {
            match parse_tokens(text) {
                Err(TokensFileError::Line { line: got, .. }) => assert_eq!(got, line, "{text}"),
                other => panic!("{text}: {other:?}"),
            }
        }
    }

    #[test]
    fn token_comparison() {
        assert!(same_token(b"secret", b"secret"));
        assert!(!same_token(b"secreT", b"secret"));
        assert!(!same_token(b"secret1", b"secret"));
        assert!(!same_token(b"", b"secret"));
    }
}
