// Which connections count as one address for the limits per address.
import { describe, expect, it } from 'vitest';
import { addressKey } from '../../../server/address.ts';

describe('addressKey', () => {
  it('keeps an IPv4 address, also written as IPv6', () => {
    expect(addressKey('127.0.0.1')).toBe('127.0.0.1');
    expect(addressKey('::ffff:127.0.0.1')).toBe('127.0.0.1');
    expect(addressKey('::FFFF:10.1.2.3')).toBe('10.1.2.3');
  });

  it('counts an IPv6 /64 as one address, however it is written', () => {
    const key = '2001:db8:1:2::/64';
    expect(addressKey('2001:db8:1:2::1')).toBe(key);
    expect(addressKey('2001:0db8:0001:0002:ffff:1:2:3')).toBe(key);
    expect(addressKey('2001:DB8:1:2:a::b')).toBe(key);
    expect(addressKey('fe80::1%eth0')).toBe('fe80:0:0:0::/64');
    expect(addressKey('2001:db8:1:3::1')).not.toBe(key);
    expect(addressKey('::1')).toBe('0:0:0:0::/64');
  });

  it('names a missing address unknown', () => {
    expect(addressKey('')).toBe('unknown');
    expect(addressKey(undefined)).toBe('unknown');
  });
});
